# frozen_string_literal: true

module Relspec
  module CLI
    # The progress of `relspec build` outside a terminal (CI logs,
    # `bin/demo > log`): a line when a package starts and one when it ends,
    # with its status, build time and done/total, so that a log shows where
    # a build is without a bar's control characters. Listens to Builder.run
    # (start, building, finished), from several threads at once.
    class BuildProgressLines
      def initialize(io)
        @io = io
        @lock = Mutex.new
      end

      # The target's first line waits for its first package: a target that
      # fails before building anything says only its error.
      def start(target, total, done)
        @lock.synchronize do
          @target = target
          @total = total
          @done = done
          @announced = false
        end
      end

      def building(entry)
        @lock.synchronize do
          announce
          say("#{@target} [#{@done}/#{@total}] started #{entry.source}")
        end
      end

      def finished(outcome)
        @lock.synchronize do
          announce
          @done += 1
          say("#{@target} [#{@done}/#{@total}] #{outcome.status} #{outcome.entry.source}#{detail(outcome)}")
        end
      end

      private

      def detail(outcome)
        return ": #{outcome.reason.to_s.lines.first.to_s.strip}" if outcome.status == :skipped

        outcome.duration ? " in #{format('%.1f', outcome.duration)} s" : ""
      end

      def announce
        return if @announced

        @announced = true
        say("#{@target}: #{@total} package#{'s' unless @total == 1}, #{@done} already built")
      end

      def say(line)
        @io.puts(line)
        @io.flush
      end
    end
  end
end
