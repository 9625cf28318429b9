# frozen_string_literal: true

require "net/http"
require "openssl"
require "uri"

module Relspec
  module Apt
    # Reads files of a repository from a local folder or over http(s), with
    # timeouts and a bounded number of retries for what may pass (timeouts,
    # refused connections, 5xx answers). A missing file is nil, not an error.
    class Fetcher
      # Raised when a file cannot be read; the message names its URL.
      class Failure < StandardError; end

      RETRIES = 3
      BACKOFF = 0.2
      REDIRECTS = 3

      attr_reader :base

      # +base+: a folder, a file:// URL or an http(s):// URL.
      def initialize(base, timeout: 10, retries: RETRIES)
        @base = base.to_s.chomp("/")
        @timeout = timeout
        @retries = retries
      end

      def remote?
        @base.match?(%r{\Ahttps?://})
      end

      def url_of(path)
        "#{@base}/#{path}"
      end

      # The bytes of +path+ below the base, or nil if there is no such file.
      def fetch(path)
        remote? ? fetch_http(url_of(path)) : fetch_file(File.join(local_base, path))
      end

      private

      def local_base
        @base.delete_prefix("file://")
      end

      def fetch_file(path)
        File.binread(path)
      rescue Errno::ENOENT, Errno::ENOTDIR
        nil
      rescue SystemCallError => e
        raise Failure, "cannot read #{path}: #{e.message}"
      end

      def fetch_http(url)
        attempt = 0
        begin
          attempt += 1
          get(URI(url))
        rescue OpenSSL::SSL::SSLError, Net::HTTPBadResponse, Net::ProtocolError => e
          raise Failure, "#{url}: #{e.message}"
        rescue Net::OpenTimeout, Net::ReadTimeout, SystemCallError, SocketError, IOError, RetryableAnswer => e
          raise Failure, "#{url}: #{describe(e)} (after #{attempt} attempts)" if attempt >= @retries

          sleep(BACKOFF * attempt)
          retry
        end
      end

      # A 5xx answer: the server may recover.
      class RetryableAnswer < StandardError; end

      # Follows a few redirects (gem servers often send downloads to storage
      # elsewhere), to http(s) only.
      def get(uri, redirects = REDIRECTS)
        Net::HTTP.start(uri.host, uri.port, use_ssl: uri.scheme == "https", open_timeout: @timeout,
                                            read_timeout: @timeout, ssl_timeout: @timeout) do |http|
          response = http.request(Net::HTTP::Get.new(uri))
          case response
          when Net::HTTPSuccess then response.body.b
          when Net::HTTPNotFound, Net::HTTPGone then nil
          when Net::HTTPServerError then raise RetryableAnswer, "HTTP #{response.code} #{response.message}"
          when Net::HTTPRedirection then follow(uri, response, redirects)
          else raise Failure, "#{uri}: HTTP #{response.code} #{response.message}"
          end
        end
      end

      def follow(uri, response, redirects)
        target = response["location"] && uri.merge(response["location"])
        unless target && %w[http https].include?(target.scheme) && redirects.positive?
          raise Failure, "#{uri}: HTTP #{response.code} redirect to #{response['location'].inspect} not followed"
        end

        get(target, redirects - 1)
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
