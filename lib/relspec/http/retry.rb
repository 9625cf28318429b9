# frozen_string_literal: true

require "net/http"
require "timeout"
require_relative "retryable"

module Relspec
  module Http
    # The one retry loop of relspec's HTTP: runs a request up to +attempts+
    # times while it fails in a way that may pass (timeouts, refused or cut
    # connections, a Retryable answer), pausing between attempts as the
    # server asked (Retry-After) or else by +backoff+. All attempts and
    # pauses share one overall +deadline+, because a per-read timeout never
    # stops a server that drips one byte at a time.
    #
    # It raises its own errors, not messages: each client words them for its
    # users (an apt download, a Launchpad page).
    class Retry
      TRANSIENT = [Net::OpenTimeout, Net::ReadTimeout, SystemCallError, SocketError, IOError, Retryable].freeze

      # Every attempt failed in a way that may pass; +last+ is the last error.
      class GaveUp < StandardError
        attr_reader :last, :attempts, :elapsed

        def initialize(last, attempts, elapsed)
          super(last.message)
          @last = last
          @attempts = attempts
          @elapsed = elapsed
        end
      end

      # The deadline passed, during an attempt or before the next one.
      class DeadlineExceeded < StandardError
        attr_reader :attempts, :elapsed

        def initialize(attempts, elapsed)
          super("deadline exceeded")
          @attempts = attempts
          @elapsed = elapsed
        end
      end

      # The server asked for a pause longer than +max_retry_after+.
      class WaitTooLong < StandardError
        attr_reader :seconds

        def initialize(seconds)
          super("asked to wait #{seconds} s")
          @seconds = seconds
        end
      end

      # Raised inside an attempt by Timeout; never leaves #run.
      class Expired < StandardError; end
      private_constant :Expired

      # +backoff+: attempt number (1 = after the first) → seconds;
      # +sleeper+ waits (tests pass one that records).
      def initialize(attempts:, deadline:, backoff:, max_retry_after:, sleeper: ->(seconds) { sleep(seconds) })
        @attempts = attempts
        @deadline = deadline
        @backoff = backoff
        @max_retry_after = max_retry_after
        @sleeper = sleeper
      end

      # The block's value (the block gets the attempt number, from 1).
      def run
        started = now
        attempt = 0
        begin
          attempt += 1
          remaining = @deadline - (now - started)
          raise Expired if remaining <= 0

          Timeout.timeout(remaining, Expired) { yield attempt }
        rescue Expired
          raise DeadlineExceeded.new(attempt, now - started)
        rescue *TRANSIENT => e
          raise GaveUp.new(e, attempt, now - started) if attempt >= @attempts

          @sleeper.call(pause(e, attempt))
          retry
        end
      end

      private

      def pause(error, attempt)
        wait = error.is_a?(Retryable) ? error.retry_after : nil
        return @backoff.call(attempt) unless wait
        raise WaitTooLong, wait if wait > @max_retry_after

        wait
      end

      def now
        Process.clock_gettime(Process::CLOCK_MONOTONIC)
      end
    end
  end
end
