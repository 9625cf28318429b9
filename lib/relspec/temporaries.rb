# frozen_string_literal: true

require "fileutils"
require "securerandom"

module Relspec
  # Names of the temporary files and folders relspec works in beside its
  # outputs, and their removal once the process that made them is gone.
  # A compile killed (SIGKILL, power loss) cannot clean up after itself; the
  # name lets a later run tell its leftovers from the work of a compile
  # still running in parallel, which it must leave alone.
  #
  # A pid alone is not enough: after a reboot or a wrap-around another
  # process (possibly the sweeping one) has it, and the leftovers would be
  # kept forever. The name also holds the process's start time (clock ticks
  # since boot, /proc/<pid>/stat), so a temporary belongs to a live process
  # only when both match. Where /proc is missing, the pid is all there is.
  module Temporaries
    # ".<base>.relspec-<pid>-<start>-<random>[<suffix>]"
    PATTERN = /\A\..+\.relspec-(\d+)-(\d+)-[0-9a-f]{8}(\.[a-z0-9.]+)?\z/
    # Names written by earlier versions, which carry the pid only.
    PID_ONLY = [/\A\..+\.relspec-(\d+)-[0-9a-f]{8}\z/, /\A\..+\.(\d+)\.tmp\z/].freeze
    PROC = "/proc"

    module_function

    # ".<base>.relspec-<pid>-<start>-<random><suffix>" in +dir+; +suffix+
    # for tools that choose a format by the name (".tar.zst").
    def path(dir, base, suffix: "")
      File.join(dir, ".#{base}.relspec-#{Process.pid}-#{start_time(Process.pid) || 0}-#{SecureRandom.hex(4)}#{suffix}")
    end

    # Removes the temporaries in +dir+ whose process no longer runs.
    # Returns the names removed.
    def sweep(dir)
      Dir.children(dir).select do |name|
        owner = owner(name)
        next false if owner.nil? || running?(*owner)

        FileUtils.rm_rf(File.join(dir, name))
        true
      end
    rescue Errno::ENOENT, Errno::ENOTDIR
      []
    end

    # [pid, start time or nil] of a temporary's name, nil for other names.
    def owner(name)
      if (match = PATTERN.match(name))
        start = match[2].to_i
        return [match[1].to_i, start.zero? ? nil : start]
      end
      PID_ONLY.each do |pattern|
        match = pattern.match(name)
        return [match[1].to_i, nil] if match
      end
      nil
    end

    # True while the process +pid+ that started at +start+ (nil: unknown)
    # runs.
    def running?(pid, start)
      return alive?(pid) if start.nil? || !File.directory?(PROC)

      start_time(pid) == start
    end

    def alive?(pid)
      Process.kill(0, pid)
      true
    rescue Errno::ESRCH
      false
    rescue Errno::EPERM # someone else's process: alive
      true
    end

    # The start time of +pid+ in clock ticks since boot, nil when unknown.
    # The command name (field 2) may hold spaces and parentheses: the fields
    # are counted after its closing one; the start time is field 22.
    def start_time(pid)
      stat = File.read(File.join(PROC, pid.to_s, "stat"))
      close = stat.rindex(")")
      close && stat[(close + 2)..].split[19]&.to_i
    rescue SystemCallError
      nil
    end
  end
end
