# frozen_string_literal: true

require "net/http"
require "openssl"
require "uri"
require_relative "../http/capped_body"
require_relative "../http/download"

module Relspec
  module Apt
    # Reads files of a repository from a local folder or over http(s)
    # (Http::Download: timeouts, redirects, a bounded number of retries for
    # what may pass, one deadline). A missing file is nil, not an error.
    class Fetcher
      # Raised when a file cannot be read; the message names its URL.
      class Failure < StandardError; end

      RETRIES = Http::Download::RETRIES
      # What is read of a file whose size nothing else bounds (gems, Release
      # files are capped lower by their callers): an endless body stops here.
      MAX_BYTES = 256 * 1024 * 1024

      attr_reader :base

      # +base+: a folder, a file:// URL or an http(s):// URL.
      def initialize(base, timeout: 10, retries: RETRIES)
        @base = base.to_s.chomp("/")
        @download = Http::Download.new(timeout: timeout, retries: retries)
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
        @download.get(URI(url)) { |uri, response| answer(uri, response, max_bytes) }
      rescue Http::Download::Failed => e
        raise Failure, e.message
      end

      def limit_reason(max_bytes)
        max_bytes == MAX_BYTES ? "the most relspec downloads (Fetcher::MAX_BYTES)" : "the most this file can hold"
      end

      def answer(uri, response, max_bytes)
        case response
        when Net::HTTPSuccess then read_body(uri, response, max_bytes)
        when Net::HTTPNotFound, Net::HTTPGone then nil
        else raise Failure, "#{uri}: HTTP #{response.code} #{response.message}"
        end
      end

      # The body, read in pieces so that an endless one stops at +max_bytes+.
      def read_body(uri, response, max_bytes)
        Http::CappedBody.read(response, max_bytes)
      rescue Http::CappedBody::TooLarge
        raise Failure, "#{uri}: the server sends more than #{max_bytes} bytes, #{limit_reason(max_bytes)}; stopped"
      end
    end
  end
end
