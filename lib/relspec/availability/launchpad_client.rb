# frozen_string_literal: true

require "json"
require "time"
require "net/http"
require "openssl"
require "timeout"
require "uri"
require_relative "../error"
require_relative "../http/capped_body"
require_relative "launchpad_page"

module Relspec
  module Availability
    # A small client of Launchpad's REST web service (anonymous, read-only,
    # Net::HTTP + JSON): the published binaries of Ubuntu's primary archive,
    # by `Archive.getPublishedBinaries`, following `next_collection_link`
    # from page to page. Answers that may pass (5xx, 429, timeouts, refused
    # connections) are retried a bounded number of times with exponential
    # backoff, honouring Retry-After; every request is counted.
    class LaunchpadClient
      DEFAULT_BASE = "https://api.launchpad.net/1.0"
      TIMEOUT = 10
      RETRIES = 4            # attempts per page, the first included
      BACKOFF = 0.5          # seconds before the 2nd attempt; doubles after
      MAX_RETRY_AFTER = 60   # a server asking for a longer pause is a failure
      MAX_PAGES = 50         # a collection longer than this is not what we asked for
      # A page of getPublishedBinaries (75 entries) is ~100 KB: an answer
      # larger than this is not Launchpad's, and reading stops there.
      MAX_ANSWER_BYTES = 8 * 1024 * 1024
      # The timeout applies to each read; a server dripping bytes would pass
      # it forever, so each page (all its attempts and pauses) also has an
      # overall deadline of this many timeouts.
      DEADLINE_FACTOR = 12

      # The service cannot answer (after the retries); the message says why.
      class Failure < Relspec::Error; end

      # Launchpad knows no such series or architecture (404 on the query).
      class UnknownSeries < Failure; end

      attr_reader :base

      # +sleeper+ waits between attempts (tests pass one that records);
      # +clock+ gives the time an HTTP-date Retry-After is counted from.
      def initialize(base: DEFAULT_BASE, timeout: TIMEOUT, retries: RETRIES, backoff: BACKOFF,
                     sleeper: ->(seconds) { sleep(seconds) }, clock: -> { Time.now })
        @base = base.to_s.chomp("/")
        @timeout = timeout
        @retries = retries
        @backoff = backoff
        @sleeper = sleeper
        @clock = clock
        @requests = 0
        @count = Mutex.new
      end

      # HTTP requests sent so far (retries and pages included).
      def requests
        @count.synchronize { @requests }
      end

      # The entries (Hashes in Launchpad's binary_package_publishing_history
      # shape) of the binaries published as +name+ in +series+/+arch+;
      # +exact+ false matches names containing +name+ (for hints).
      def published_binaries(name, series, arch, exact: true)
        url = query_url(name, series, arch, exact)
        entries = []
        MAX_PAGES.times do
          page = get_json(url, "#{series}/#{arch}")
          entries.concat(page.entries)
          url = page.next_link
          return entries unless url
        end
        raise Failure, "Launchpad: more than #{MAX_PAGES} pages for #{name} on #{series}/#{arch}"
      end

      private

      def query_url(name, series, arch, exact)
        query = URI.encode_www_form("ws.op" => "getPublishedBinaries", "binary_name" => name,
                                    "exact_match" => exact.to_s, "status" => "Published",
                                    "distro_arch_series" => "#{@base}/ubuntu/#{series}/#{arch}")
        "#{@base}/ubuntu/+archive/primary?#{query}"
      end

      # A retryable answer, with the pause the server asked for (or nil).
      class Retryable < StandardError
        attr_reader :retry_after

        def initialize(message, retry_after = nil)
          super(message)
          @retry_after = retry_after
        end
      end

      # Raised when a page passed its overall deadline.
      class DeadlineExceeded < StandardError; end

      def get_json(url, where)
        attempt = 0
        started = now
        begin
          attempt += 1
          remaining = (@timeout * DEADLINE_FACTOR) - (now - started)
          raise DeadlineExceeded if remaining <= 0

          parse(Timeout.timeout(remaining, DeadlineExceeded) { get(URI(url), where) }, url)
        rescue DeadlineExceeded
          raise Failure, format("Launchpad: %<url>s: not complete after %<elapsed>.1f s, the deadline of a page " \
                                "(%<factor>d × the timeout %<timeout>s s; after %<attempts>d attempts)",
                                url: url, elapsed: now - started, factor: DEADLINE_FACTOR, timeout: @timeout,
                                attempts: attempt)
        rescue Net::OpenTimeout, Net::ReadTimeout, SystemCallError, SocketError, IOError, Retryable => e
          raise Failure, "Launchpad: #{url}: #{describe(e)} (after #{attempt} attempts)" if attempt >= @retries

          @sleeper.call(pause(e, attempt, url))
          retry
        rescue OpenSSL::SSL::SSLError, Net::HTTPBadResponse, Net::ProtocolError, URI::InvalidURIError => e
          raise Failure, "Launchpad: #{url}: #{e.message}"
        end
      end

      def pause(error, attempt, url)
        wait = error.is_a?(Retryable) ? error.retry_after : nil
        return @backoff * (2**(attempt - 1)) unless wait
        raise Failure, "Launchpad: #{url}: asked to wait #{wait} s (more than #{MAX_RETRY_AFTER})" if wait > MAX_RETRY_AFTER

        wait
      end

      def get(uri, where)
        raise Failure, "Launchpad: #{uri} is not an http(s) URL" unless %w[http https].include?(uri.scheme)

        @count.synchronize { @requests += 1 }
        http = Net::HTTP.new(uri.host, uri.port)
        http.use_ssl = uri.scheme == "https"
        http.open_timeout = http.read_timeout = http.ssl_timeout = @timeout
        http.max_retries = 0 # Net::HTTP would silently resend a timed-out GET; the retries are counted here
        http.start do
          request = Net::HTTP::Get.new(uri)
          request["Accept"] = "application/json"
          # `return` leaves before Net::HTTP reads the rest of a body that
          # was not wanted (an error page can be endless too).
          http.request(request) { |response| return answer(response, uri, where) }
        end
      end

      def now
        Process.clock_gettime(Process::CLOCK_MONOTONIC)
      end

      # The body, read in pieces so that an endless one stops at the cap.
      def read_body(response, uri)
        Http::CappedBody.read(response, MAX_ANSWER_BYTES).force_encoding(Encoding::UTF_8)
      rescue Http::CappedBody::TooLarge
        raise Failure, "Launchpad: #{uri}: the answer is larger than #{MAX_ANSWER_BYTES} bytes (MAX_ANSWER_BYTES); stopped"
      end

      def answer(response, uri, where)
        case response
        when Net::HTTPSuccess then read_body(response, uri)
        when Net::HTTPNotFound, Net::HTTPBadRequest
          raise UnknownSeries, "Launchpad has no Ubuntu series/architecture #{where} (#{uri.host}: HTTP #{response.code})"
        when Net::HTTPTooManyRequests, Net::HTTPServerError
          raise Retryable.new("HTTP #{response.code} #{response.message}", retry_after(response["Retry-After"]))
        else raise Failure, "Launchpad: #{uri}: HTTP #{response.code} #{response.message}"
        end
      end

      # Seconds (the form Launchpad and most services send); an HTTP date
      # is honoured too.
      def retry_after(value)
        return nil if value.nil? || value.strip.empty?
        return Integer(value.strip, 10) if value.strip.match?(/\A\d+\z/)

        [(Time.httpdate(value) - @clock.call).ceil, 0].max
      rescue ArgumentError
        nil
      end

      def parse(body, url)
        LaunchpadPage.parse(body, url, failure: Failure)
      end

      def describe(error)
        case error
        when Net::OpenTimeout, Net::ReadTimeout then "no answer within #{@timeout} s"
        else error.message
        end
      end
    end
  end
end
