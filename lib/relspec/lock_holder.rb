# frozen_string_literal: true

require "etc"
require_relative "temporaries"

module Relspec
  # Who holds a flock on an open file, as /proc tells: "relspec build (pid
  # 123, since 2026-11-27 08:10:05 UTC)", for the message of the process
  # that is refused or waits. The holder may end in between, and another
  # user's process may hide its command line: then less is said, never
  # something wrong.
  module LockHolder
    PROC = "/proc"

    module_function

    # The holder of +file+'s flock, or "another process".
    def of(file)
      pid = pid_of(file)
      return "another process" unless pid

      since = started(pid)
      "#{command_of(pid)} (pid #{pid}#{", since #{since}" if since})"
    end

    # The pid in /proc/locks holding a lock on +file+'s device and inode.
    def pid_of(file)
      stat = file.stat
      device = format("%02x:%02x:%d", stat.dev_major, stat.dev_minor, stat.ino)
      line = File.foreach(File.join(PROC, "locks")).find { |entry| !entry.include?("->") && entry.split[5] == device }
      line&.split&.fetch(4)&.to_i
    rescue SystemCallError
      nil
    end

    # "relspec build" from the holder's command line, else its program name.
    def command_of(pid)
      args = File.binread(File.join(PROC, pid.to_s, "cmdline")).split("\0")
      at = args.index { |arg| File.basename(arg) == "relspec" }
      at ? "relspec #{args[at + 1]}" : File.basename(args.first.to_s)
    rescue SystemCallError
      "a process"
    end

    # When +pid+ started, in UTC: the boot time (/proc/stat's btime) plus
    # its start in clock ticks since boot; nil when /proc does not say.
    def started(pid)
      ticks = Temporaries.start_time(pid)
      boot = File.foreach(File.join(PROC, "stat")).find { |line| line.start_with?("btime ") }&.split&.last
      return nil unless ticks && boot

      Time.at(Integer(boot, 10) + (ticks / Etc.sysconf(Etc::SC_CLK_TCK))).utc.strftime("%Y-%m-%d %H:%M:%S UTC")
    rescue SystemCallError, ArgumentError
      nil
    end
  end
end
