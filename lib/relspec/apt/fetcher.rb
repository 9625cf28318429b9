# frozen_string_literal: true

require "net/http"
require "openssl"
require "uri"
require_relative "../http/capped_body"
require_relative "../http/client"
require_relative "../http/retry"

module Relspec
  module Apt
    # Reads files of a repository from a local folder or over http(s), with
    # timeouts and a bounded number of retries for what may pass (timeouts,
    # refused connections, 5xx answers, honouring Retry-After up to the
    # deadline). A missing file is nil, not an error.
    class Fetcher
      # Raised when a file cannot be read; the message names its URL.
      class Failure < StandardError; end

      RETRIES = 3
      BACKOFF = 0.2
      REDIRECTS = 3
      # --timeout bounds each wait for the server; a download as a whole,
      # with its retries, gets this many times that: a server dripping one
      # byte per second never makes relspec wait forever (10 s → 2 min).
      DEADLINE_FACTOR = 12
      # What is read of a file whose size nothing else bounds (gems, Release
      # files are capped lower by their callers): an endless body stops here.
      MAX_BYTES = 256 * 1024 * 1024

      attr_reader :base

      # +base+: a folder, a file:// URL or an http(s):// URL.
      def initialize(base, timeout: 10, retries: RETRIES)
        @base = base.to_s.chomp("/")
        @timeout = timeout
        @client = Http::Client.new(timeout: timeout)
        @retry = Http::Retry.new(attempts: retries, deadline: deadline, backoff: ->(attempt) { BACKOFF * attempt },
                                 max_retry_after: deadline)
      end

      def remote?
        @base.match?(%r{\Ahttps?://})
      end

      def url_of(path)
        "#{@base}/#{path}"
      end

      # The bytes of +path+ below the base, or nil if there is no such file.
      # More than +max_bytes+ is a Failure: nothing past it is read.
      def fetch(path, max_bytes: MAX_BYTES)
        remote? ? fetch_http(url_of(path), max_bytes) : fetch_file(File.join(local_base, path), max_bytes)
      end

      # The overall time one download may take, retries included.
      def deadline
        @timeout * DEADLINE_FACTOR
      end

      private

      def local_base
        @base.delete_prefix("file://")
      end

      # Only regular files: a FIFO would block forever, /dev/zero never end.
      def fetch_file(path, max_bytes)
        stat = File.stat(path)
        raise Failure, "cannot read #{path}: not a regular file (#{stat.ftype})" unless stat.file?
        raise Failure, "#{path} is larger than #{max_bytes} bytes, #{limit_reason(max_bytes)}" if stat.size > max_bytes

        File.binread(path)
      rescue Errno::ENOENT, Errno::ENOTDIR
        nil
      rescue SystemCallError => e
        raise Failure, "cannot read #{path}: #{e.message}"
      end

      def fetch_http(url, max_bytes)
        @retry.run { get(URI(url), max_bytes) }
      rescue OpenSSL::SSL::SSLError, Net::HTTPBadResponse, Net::ProtocolError => e
        raise Failure, "#{url}: #{e.message}"
      rescue Http::Retry::DeadlineExceeded => e
        raise Failure, "#{url}: not complete after #{elapsed(e)} s, the deadline of a download " \
                       "(#{DEADLINE_FACTOR} × --timeout #{@timeout}; after #{attempts(e.attempts)})"
      rescue Http::Retry::GaveUp => e
        raise Failure, "#{url}: #{describe(e.last)} (after #{attempts(e.attempts)}, #{elapsed(e)} s in all)"
      rescue Http::Retry::WaitTooLong => e
        raise Failure, "#{url}: asked to wait #{e.seconds} s, more than the deadline of a download (#{deadline} s)"
      end

      def elapsed(error)
        format("%.1f", error.elapsed)
      end

      def attempts(count)
        count == 1 ? "1 attempt" : "#{count} attempts"
      end

      def limit_reason(max_bytes)
        max_bytes == MAX_BYTES ? "the most relspec downloads (Fetcher::MAX_BYTES)" : "the most this file can hold"
      end

      # Follows a few redirects (gem servers often send downloads to storage
      # elsewhere), to http(s) only.
      def get(uri, max_bytes, redirects = REDIRECTS)
        @client.get(uri) { |response| answer(uri, response, max_bytes, redirects) }
      end

      def answer(uri, response, max_bytes, redirects)
        case response
        when Net::HTTPSuccess then read_body(uri, response, max_bytes)
        when Net::HTTPNotFound, Net::HTTPGone then nil
        when Net::HTTPServerError then raise Http::Retryable.answer(response)
        when Net::HTTPRedirection then follow(uri, response, max_bytes, redirects)
        else raise Failure, "#{uri}: HTTP #{response.code} #{response.message}"
        end
      end

      # The body, read in pieces so that an endless one stops at +max_bytes+.
      def read_body(uri, response, max_bytes)
        Http::CappedBody.read(response, max_bytes)
      rescue Http::CappedBody::TooLarge
        raise Failure, "#{uri}: the server sends more than #{max_bytes} bytes, #{limit_reason(max_bytes)}; stopped"
      end

      def follow(uri, response, max_bytes, redirects)
        target = response["location"] && uri.merge(response["location"])
        unless target && %w[http https].include?(target.scheme) && redirects.positive?
          raise Failure, "#{uri}: HTTP #{response.code} redirect to #{response['location'].inspect} not followed"
        end

        get(target, max_bytes, redirects - 1)
      end

      def describe(error)
        case error
        when Net::OpenTimeout, Net::ReadTimeout then "no answer within #{@timeout} s per read"
        else error.message
        end
      end
    end
  end
end
