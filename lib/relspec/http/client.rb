# frozen_string_literal: true

require "net/http"
require "openssl"
require "uri"

module Relspec
  module Http
    # One GET with relspec's timeouts: +timeout+ bounds the connection and
    # each read. Net::HTTP's own silent resend of a timed-out GET is off:
    # attempts are counted by Http::Retry, so that messages say how many.
    class Client
      def initialize(timeout:)
        @timeout = timeout
      end

      # Yields the response (a Net::HTTPResponse whose body is not read yet)
      # and returns the block's value. Leaving the block leaves the
      # connection: a body the block did not read (an endless error page) is
      # never read to its end.
      def get(uri, headers = {})
        Net::HTTP.start(uri.host, uri.port, use_ssl: uri.scheme == "https", open_timeout: @timeout,
                                            read_timeout: @timeout, ssl_timeout: @timeout) do |http|
          http.max_retries = 0
          request = Net::HTTP::Get.new(uri)
          headers.each { |name, value| request[name] = value }
          http.request(request) { |response| return yield(response) }
        end
      end
    end
  end
end
