# frozen_string_literal: true

require_relative "../compile"
require_relative "../printable"
require_relative "discarded_lock"

module Relspec
  module CLI
    # `relspec compile SPEC`: the source packages of everything the release
    # builds, plan.yml per target, the lock and the osdeps files.
    class CompileCommand
      def initialize(path:, out:, jobs:, timeout:, out_io:, progress_io: nil, err_io: $stderr, discard_lock: false,
                     check: true)
        @err = err_io
        @discard_lock = discard_lock
        @check = check
        @path = path
        @out = out
        @jobs = jobs
        @timeout = timeout
        @io = out_io
        @progress_io = progress_io
      end

      def call
        result = Compile.run(@path, out: @out, jobs: @jobs, timeout: @timeout, progress: progress_bar,
                                    discard_lock: @discard_lock, check: @check,
                                    planned: ->(planned) { DiscardedLock.warn(planned, @err) })
        note_repaired(result.repaired)
        if result.written.empty? && !result.lock_changed && result.osdeps_written.zero?
          @io.puts("#{result.release}: nothing changed (#{result.unchanged.size} source packages up to date)")
        else
          result.written.each { |dir| @io.puts("wrote #{Printable.text(dir)}") } # --out is the command line's
          @io.puts("#{result.release}: #{result.written.size} source packages written, #{result.unchanged.size} unchanged, " \
                   "#{result.published.size} already published; #{result.lock_changed ? 'wrote' : 'kept'} " \
                   "#{Printable.text(result.lock_path)}")
          note_unchecked(result.unchecked)
        end
        0
      end

      private

      # Said once, when sources are written (a compile with nothing changed
      # stays one line).
      def note_unchecked(unchecked)
        return if unchecked.empty?

        @io.puts("note: OS dependencies not checked on #{unchecked.map { |r| "#{r.target} (#{r.reason})" }.join('; ')}")
      end

      # A damaged cache entry is not an error (it is made again), but a
      # cache that breaks again and again points at the disk.
      def note_repaired(paths)
        paths.each do |path|
          @err.puts("warning: the orig cache entry #{path} was damaged (its SHA256 differs from the one " \
                    "recorded when it was made); made it again")
        end
      end

      # A bar on a terminal (stderr), nothing otherwise or with --quiet.
      def progress_bar
        return nil unless @progress_io&.tty?

        require "tty-progressbar"
        bar = nil
        lambda do |done, total|
          bar ||= TTY::ProgressBar.new("source packages [:bar] :current/:total", total: total, output: @progress_io,
                                                                                 width: 30, clear: true)
          bar.current = done
        end
      end
    end
  end
end
