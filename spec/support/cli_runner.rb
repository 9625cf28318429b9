# frozen_string_literal: true

require "open3"
require "rbconfig"
require "tmpdir"
require "fileutils"

# Runs the real relspec executable in a child process, as a user would, and
# notes the child's peak memory (GNU time's maximum resident set size) so
# the hostile-input corpus can hold every run to its bound (docs/limits.md).
module CliRunner
  ROOT = File.expand_path("../..", __dir__)
  EXE = File.join(ROOT, "exe", "relspec")
  TIME = "/usr/bin/time" # GNU time (Debian package `time`, installed by bin/setup)
  # The memory bound of the hostile-input corpus: 500 MB.
  HOSTILE_MAX_RSS_KIB = 500 * 1000 * 1000 / 1024

  Run = Struct.new(:stdout, :stderr, :status, :max_rss_kib, keyword_init: true) do
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
    Dir.mktmpdir("relspec-run") do |dir|
      report = File.join(dir, "rss")
      # -q: the report holds the number only, whatever the exit status
      stdout, stderr, status = Open3.capture3({ "XDG_CACHE_HOME" => CACHE }.merge(env), TIME, "-q", "-o", report,
                                              "-f", "%M", RbConfig.ruby, EXE, *args, **options)
      run = Run.new(stdout: stdout, stderr: stderr, status: status, max_rss_kib: File.read(report).to_i)
      relspec_runs << run
      run
    end
  end

  # The runs of the current example.
  def relspec_runs
    @relspec_runs ||= []
  end
end
