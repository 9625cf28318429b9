# frozen_string_literal: true

require "open3"
require "rbconfig"
require "tmpdir"
require "fileutils"

# Runs the real relspec executable in a child process, as a user would.
module CliRunner
  ROOT = File.expand_path("../..", __dir__)
  EXE = File.join(ROOT, "exe", "relspec")

  Run = Struct.new(:stdout, :stderr, :status, keyword_init: true) do
    def exit_code
      status.exitstatus
    end
  end

  # Caches go to a folder of the test run, never to the user's.
  CACHE = Dir.mktmpdir("relspec-test-cache")
  at_exit { FileUtils.rm_rf(CACHE) }

  # +env+: more environment variables; +umask+: the child's umask.
  def relspec(*args, chdir: ROOT, env: {}, umask: nil)
    options = { chdir: chdir, stdin_data: "" }
    options[:umask] = umask if umask
    stdout, stderr, status = Open3.capture3({ "XDG_CACHE_HOME" => CACHE }.merge(env), RbConfig.ruby, EXE, *args, **options)
    Run.new(stdout: stdout, stderr: stderr, status: status)
  end
end
