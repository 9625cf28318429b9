# frozen_string_literal: true

require "open3"
require "rbconfig"

# Runs the real relspec executable in a child process, as a user would.
module CliRunner
  ROOT = File.expand_path("../..", __dir__)
  EXE = File.join(ROOT, "exe", "relspec")

  Run = Struct.new(:stdout, :stderr, :status, keyword_init: true) do
    def exit_code
      status.exitstatus
    end
  end

  def relspec(*args, chdir: ROOT)
    stdout, stderr, status = Open3.capture3(RbConfig.ruby, EXE, *args, chdir: chdir, stdin_data: "")
    Run.new(stdout: stdout, stderr: stderr, status: status)
  end
end
