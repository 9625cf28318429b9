# frozen_string_literal: true

require "net/http"
require "openssl"
require "uri"
require_relative "client"
require_relative "retry"
require_relative "retryable"

module Relspec
  module Http
    # One download as every relspec reader of http(s) makes it (apt indices,
    # gems, archive imports): a GET with the --timeout on each connection and
    # read, a few redirects followed (forges and gem servers send downloads
    # elsewhere; to http(s) only), tried again while it fails in a way that
    # may pass (timeouts, refused or cut connections, a 5xx; Retry-After
    # honoured), all within one deadline of DEADLINE_FACTOR × the timeout:
    # a per-read timeout never stops a server that drips one byte at a time.
    class Download
      RETRIES = 3
      BACKOFF = 0.2
      REDIRECTS = 3
      # 10 s → 2 min for a download, its retries included.
      DEADLINE_FACTOR = 12

      # The download cannot be made; the message names the URL and why.
      class Failed < StandardError; end

      attr_reader :timeout

      # +sleeper+ waits between attempts (tests pass one that records).
      def initialize(timeout:, retries: RETRIES, sleeper: ->(seconds) { sleep(seconds) })
        @timeout = timeout
        @client = Client.new(timeout: timeout)
        @retry = Retry.new(attempts: retries, deadline: deadline, backoff: ->(attempt) { BACKOFF * attempt },
                           max_retry_after: deadline, sleeper: sleeper)
      end

      # The overall time one download may take, retries included.
      def deadline
        @timeout * DEADLINE_FACTOR
      end

      # The block's value for the answer the redirects end at (the block
      # gets that URI and the Net::HTTPResponse, its body not read yet);
      # a 5xx is asked again instead. Errors the block raises pass through.
      def get(uri, &block)
        @retry.run { follow(uri, REDIRECTS, &block) }
      rescue OpenSSL::SSL::SSLError, Net::HTTPBadResponse, Net::ProtocolError => e
        raise Failed, "#{uri}: #{e.message}"
      rescue Retry::DeadlineExceeded => e
        raise Failed, "#{uri}: not complete after #{elapsed(e)} s, the deadline of a download " \
                      "(#{DEADLINE_FACTOR} × --timeout #{@timeout}; after #{attempts(e.attempts)})"
      rescue Retry::GaveUp => e
        raise Failed, "#{uri}: #{describe(e.last)} (after #{attempts(e.attempts)}, #{elapsed(e)} s in all)"
      rescue Retry::WaitTooLong => e
        raise Failed, "#{uri}: asked to wait #{e.seconds} s, more than the deadline of a download (#{deadline} s)"
      end

      private

      # A redirect's target, followed once its connection is left.
      Moved = Struct.new(:uri)
      private_constant :Moved

      def follow(uri, redirects, &)
        answer = @client.get(uri) do |response|
          case response
          when Net::HTTPServerError then raise Retryable.answer(response)
          when Net::HTTPRedirection then Moved.new(redirect(uri, response, redirects))
          else yield(uri, response)
          end
        end
        answer.is_a?(Moved) ? follow(answer.uri, redirects - 1, &) : answer
      end

      def redirect(uri, response, redirects)
        target = response["location"] && uri.merge(response["location"])
        return target if target && %w[http https].include?(target.scheme) && redirects.positive?

        raise Failed, "#{uri}: HTTP #{response.code} redirect to #{response['location'].inspect} not followed"
      rescue URI::Error
        raise Failed, "#{uri}: HTTP #{response.code} redirect to #{response['location'].inspect}, which is not a URL"
      end

      def describe(error)
        case error
        when Net::OpenTimeout, Net::ReadTimeout then "no answer within #{@timeout} s per read"
        else error.message
        end
      end

      def elapsed(error)
        format("%.1f", error.elapsed)
      end

      def attempts(count)
        count == 1 ? "1 attempt" : "#{count} attempts"
      end
    end
  end
end
