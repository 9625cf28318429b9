# frozen_string_literal: true

require "json"
require "net/http"
require "openssl"
require "uri"
require_relative "../error"
require_relative "../http/capped_body"
require_relative "launchpad_page"
require_relative "../http/client"
require_relative "../http/retry"

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
        @clock = clock
        @client = Http::Client.new(timeout: timeout)
        @retry = Http::Retry.new(attempts: retries, deadline: timeout * DEADLINE_FACTOR, sleeper: sleeper,
                                 backoff: ->(attempt) { backoff * (2**(attempt - 1)) },
                                 max_retry_after: MAX_RETRY_AFTER)
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

      def get_json(url, where)
        parse(@retry.run { get(URI(url), where) }, url)
      rescue Http::Retry::DeadlineExceeded => e
        raise Failure, format("Launchpad: %<url>s: not complete after %<elapsed>.1f s, the deadline of a page " \
                              "(%<factor>d × the timeout %<timeout>s s; after %<attempts>d attempts)",
                              url: url, elapsed: e.elapsed, factor: DEADLINE_FACTOR, timeout: @timeout,
                              attempts: e.attempts)
      rescue Http::Retry::GaveUp => e
        raise Failure, "Launchpad: #{url}: #{describe(e.last)} (after #{e.attempts} attempts)"
      rescue Http::Retry::WaitTooLong => e
        raise Failure, "Launchpad: #{url}: asked to wait #{e.seconds} s (more than #{MAX_RETRY_AFTER})"
      rescue OpenSSL::SSL::SSLError, Net::HTTPBadResponse, Net::ProtocolError, URI::InvalidURIError => e
        raise Failure, "Launchpad: #{url}: #{e.message}"
      end

      def get(uri, where)
        raise Failure, "Launchpad: #{uri} is not an http(s) URL" unless %w[http https].include?(uri.scheme)

        @count.synchronize { @requests += 1 }
        @client.get(uri, "Accept" => "application/json") { |response| answer(response, uri, where) }
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
          raise Http::Retryable.answer(response, now: @clock.call)
        else raise Failure, "Launchpad: #{uri}: HTTP #{response.code} #{response.message}"
        end
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
