# frozen_string_literal: true

module Relspec
  module CLI
    # The progress of `relspec build` on a terminal: packages done/total,
    # the ones building now and the elapsed time, one bar per target.
    # Listens to Builder.run (start, building, finished).
    class BuildProgress
      def initialize(io)
        require "tty-progressbar"
        @io = io
        @building = []
        @lock = Mutex.new
      end

      def start(target, total, done)
        @bar&.finish
        @building.clear
        @bar = TTY::ProgressBar.new("#{target} [:bar] :current/:total :elapsed :building", total: [total, 1].max,
                                                                                           output: @io, width: 24, clear: true)
        @bar.advance(done, building: "")
      end

      def building(entry)
        @lock.synchronize do
          @building << entry.source
          @bar.advance(0, building: now)
        end
      end

      def finished(outcome)
        @lock.synchronize do
          @building.delete(outcome.entry.source)
          @bar.advance(1, building: now)
        end
      end

      private

      def now
        @building.empty? ? "" : "building #{@building.join(', ')}"
      end
    end
  end
end
