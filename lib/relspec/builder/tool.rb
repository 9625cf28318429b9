# frozen_string_literal: true

require_relative "../error"

module Relspec
  module Builder
    # Runs the external tools of a build (dpkg-source, dpkg-buildpackage,
    # sbuild, mmdebstrap) with their output appended to a log file, and
    # keeps their process ids so that an interrupted run can stop them
    # (each runs in its own process group, with its children).
    class Tool
      # What a build's tools must not inherit from relspec's own process:
      # under `bundle exec`, every ruby child would see only relspec's bundle.
      OUTSIDE_BUNDLE = %w[RUBYOPT RUBYLIB BUNDLE_GEMFILE BUNDLER_SETUP BUNDLE_BIN_PATH BUNDLER_VERSION GEM_HOME
                          GEM_PATH].to_h { |name| [name, nil] }.freeze
      STOP_GRACE = 5 # seconds between TERM and KILL when a run is interrupted

      def initialize
        @pids = {}
        @lock = Mutex.new
      end

      # Runs +command+; raises BuildError naming +source+, the tool, its exit
      # status and +log+ when it fails. +stdin+: a file to read input from;
      # +name+: the tool the failure names when +command+ is a wrapper that
      # execs it (unshare … dpkg-buildpackage: the exit status is the tool's).
      def run(source, command, log:, chdir: nil, env: {}, stdin: nil, name: File.basename(command.first))
        options = { out: [log, "a"], err: %i[child out], pgroup: true, in: stdin || File::NULL }
        options[:chdir] = chdir if chdir
        File.open(log, "a") { |file| file.puts("$ #{command.join(' ')}") }
        status = wait(spawn(OUTSIDE_BUNDLE.merge(env), command, options))
        return if status.success?

        raise BuildError, "#{source}: #{name} failed " \
                          "(#{status.exitstatus ? "exit status #{status.exitstatus}" : "signal #{status.termsig}"}), " \
                          "see #{log}"
      end

      # Stops every tool still running (TERM, then KILL after STOP_GRACE).
      def stop_all
        pids = @lock.synchronize { @pids.keys }
        pids.each { |pid| signal("TERM", pid) }
        deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + STOP_GRACE
        sleep 0.1 while @lock.synchronize { @pids.any? } && Process.clock_gettime(Process::CLOCK_MONOTONIC) < deadline
        @lock.synchronize { @pids.keys }.each { |pid| signal("KILL", pid) }
      end

      private

      def spawn(env, command, options)
        pid = Process.spawn(env, *command, **options)
        @lock.synchronize { @pids[pid] = true }
        pid
      rescue SystemCallError => e
        raise BuildError, "cannot run #{command.first}: #{e.message.sub(/ - .*\z/, '')} (is it installed? bin/setup installs it)"
      end

      def wait(pid)
        Process.wait2(pid).last
      ensure
        @lock.synchronize { @pids.delete(pid) }
      end

      def signal(name, pid)
        Process.kill(name, -pid)
      rescue Errno::ESRCH, Errno::EPERM
        nil
      end
    end
  end
end
