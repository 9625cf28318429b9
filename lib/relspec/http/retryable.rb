# frozen_string_literal: true

require "time"

module Relspec
  module Http
    # An answer worth asking again (a 5xx, a 429), with the pause the server
    # asked for in Retry-After (seconds), or nil when it named none.
    class Retryable < StandardError
      attr_reader :retry_after

      # The Retryable for +response+ (a Net::HTTPResponse); an HTTP-date
      # Retry-After is counted from +now+.
      def self.answer(response, now: Time.now)
        new("HTTP #{response.code} #{response.message}", retry_after(response["Retry-After"], now))
      end

      # Seconds (the form most services send); an HTTP date is honoured too;
      # anything else is no wish.
      def self.retry_after(value, now)
        return nil if value.nil? || value.strip.empty?
        return Integer(value.strip, 10) if value.strip.match?(/\A\d+\z/)

        [(Time.httpdate(value) - now).ceil, 0].max
      rescue ArgumentError
        nil
      end

      def initialize(message, retry_after = nil)
        super(message)
        @retry_after = retry_after
      end
    end
  end
end
