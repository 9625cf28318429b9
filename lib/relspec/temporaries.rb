# frozen_string_literal: true

require "fileutils"
require "securerandom"

module Relspec
  # Names of the temporary files and folders relspec works in beside its
  # outputs, and their removal once the process that made them is gone.
  # A compile killed (SIGKILL, power loss) cannot clean up after itself; the
  # pid in the name lets a later run tell its leftovers from the work of a
  # compile still running in parallel, which it must leave alone.
  module Temporaries
    PATTERN = /\A\..+\.relspec-(\d+)-[0-9a-f]{8}\z/
    # AtomicFile's temporary files: ".<name>.<pid>.tmp"
    ATOMIC = /\A\..+\.(\d+)\.tmp\z/

    module_function

    # ".<base>.relspec-<pid>-<random>" in +dir+.
    def path(dir, base)
      File.join(dir, ".#{base}.relspec-#{Process.pid}-#{SecureRandom.hex(4)}")
    end

    # Removes the temporaries in +dir+ whose process no longer runs.
    # Returns the names removed.
    def sweep(dir)
      Dir.children(dir).select do |name|
        pid = (PATTERN.match(name) || ATOMIC.match(name))&.[](1)&.to_i
        next false if pid.nil? || running?(pid)

        FileUtils.rm_rf(File.join(dir, name))
        true
      end
    rescue Errno::ENOENT, Errno::ENOTDIR
      []
    end

    def running?(pid)
      return true if pid == Process.pid

      Process.kill(0, pid)
      true
    rescue Errno::ESRCH
      false
    rescue Errno::EPERM # someone else's process: alive
      true
    end
  end
end
