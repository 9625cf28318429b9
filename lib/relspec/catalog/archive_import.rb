# frozen_string_literal: true

require "digest"
require "fileutils"
require "json"
require "time"
require "uri"
require "stringio"
require "zlib"
require "rubygems/package"
require_relative "../atomic_file"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../http/download"
require_relative "../http/capped_body"

module Relspec
  class Catalog
    # A package autoproj imports from a tarball (`type: archive`). It has no
    # commit: as the seed did, its upstream version is made of the archive's
    # time of last modification (the server's Last-Modified, a local file's
    # mtime), and its .orig is the archive's tree with every file dated so,
    # so that two compiles give the same bytes. The archive is fetched once
    # into relspec's cache (<cache>/<sha256 of the url>/), with its time and
    # checksum beside it; the checksum goes into the catalog (vcs.sha256),
    # and so into the lock. Delete the cache entry to fetch it again.
    class ArchiveImport
      MAX_BYTES = 1 << 30
      SCHEMES = %w[http https file].freeze

      # +cache+: the folder of fetched archives; +timeout+: seconds per
      # connection and read (--timeout; Http::Download's deadline and retries).
      def initialize(cache:, timeout:)
        @cache = cache
        @download = Http::Download.new(timeout: timeout)
      end

      # The package with its version's time and the archive's checksum.
      def resolve(package)
        entry = fetched(package)
        vcs = Vcs.new(**package.vcs.to_h.transform_keys(&:to_sym), sha256: entry.fetch("sha256")).freeze
        package.with(vcs: vcs, commit_time: entry.fetch("mtime"))
      end

      # The archive of a resolved package, checked against its checksum
      # (a cache entry is untrusted): the path, or an InvalidInput.
      def path_of(package)
        path = archive_path(package.vcs.url)
        return path if File.file?(path) && Digest::SHA256.file(path).hexdigest == package.vcs.sha256

        fail_with(package, "the archive in relspec's cache (#{path}) is missing or is not the one planned " \
                           "(sha256 #{package.vcs.sha256})", "plan again, so that relspec fetches it again")
      end

      private

      def fetched(package)
        meta = "#{archive_path(package.vcs.url)}.json"
        entry = read_meta(meta)
        return entry if entry && File.file?(archive_path(package.vcs.url))

        download(package, archive_path(package.vcs.url), meta)
      end

      def read_meta(path)
        data = JSON.parse(File.read(path))
        valid = data.is_a?(Hash) && data["sha256"].to_s.match?(/\A\h{64}\z/) &&
                data["mtime"].to_s.match?(/\A\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ\z/)
        valid ? data : nil
      rescue SystemCallError, JSON::ParserError
        nil
      end

      def archive_path(url)
        name = File.basename(URI.parse(url).path.to_s)
        name = "archive" unless name.match?(/\A[A-Za-z0-9][A-Za-z0-9._+~-]*\z/)
        File.join(@cache, Digest::SHA256.hexdigest(url)[0, 32], name)
      rescue URI::InvalidURIError
        File.join(@cache, Digest::SHA256.hexdigest(url)[0, 32], "archive")
      end

      def download(package, path, meta)
        body, mtime = read_source(package)
        FileUtils.mkdir_p(File.dirname(path))
        AtomicFile.write(path, body)
        entry = { "sha256" => Digest::SHA256.hexdigest(body), "mtime" => mtime.utc.strftime("%Y-%m-%dT%H:%M:%SZ"),
                  "url" => package.vcs.url }
        AtomicFile.write(meta, "#{JSON.generate(entry)}\n")
        entry
      end

      # [bytes, Time] of the archive at the package's url.
      def read_source(package)
        uri = URI.parse(package.vcs.url)
        unless SCHEMES.include?(uri.scheme)
          fail_with(package, "archive url #{package.vcs.url} is not http, https or file",
                    "autoproj's archive importer also knows ftp: serve the archive over http")
        end
        uri.scheme == "file" ? read_file(package, uri.path) : read_http(package, uri)
      rescue URI::InvalidURIError
        fail_with(package, "archive url #{package.vcs.url.inspect} is not a URL", "fix the package set's url")
      end

      def read_file(package, path)
        [File.binread(path), File.mtime(path)]
      rescue SystemCallError => e
        fail_with(package, "cannot read the archive #{path}: #{e.message}", "check the package set's url")
      end

      # Release archives on forges are served from elsewhere: redirects
      # are followed (Http::Download, as every download of relspec).
      def read_http(package, uri)
        @download.get(uri) do |at, response|
          unless response.is_a?(Net::HTTPOK)
            fail_with(package, "#{at} answered #{response.code} #{response.message}".strip, "check the package set's url")
          end
          body = Http::CappedBody.read(response, MAX_BYTES)
          modified = response["Last-Modified"]
          [body, modified ? Time.httpdate(modified) : newest_member_time(package, at, body)]
        end
      rescue Http::CappedBody::TooLarge
        fail_with(package, "the archive at #{uri} is larger than #{MAX_BYTES >> 20} MiB", "check the package set's url")
      rescue ArgumentError
        fail_with(package, "#{uri} gives a Last-Modified time that is not an HTTP date", "check the server")
      rescue Http::Download::Failed => e
        fail_with(package, "cannot fetch #{e.message}", "check the url and the network")
      end

      # Without Last-Modified (forges' generated archives), the newest time
      # of the archive's files: the same bytes give the same time. Read for
      # tar and tar.gz archives.
      def newest_member_time(package, uri, body)
        io = StringIO.new(body)
        io = Zlib::GzipReader.new(io) if body.start_with?("\x1F\x8B".b)
        times = []
        Gem::Package::TarReader.new(io) { |tar| tar.each { |entry| times << entry.header.mtime } }
        raise Gem::Package::TarInvalidError, "no files" if times.empty?

        Time.at(times.max).utc
      rescue Zlib::Error, Gem::Package::TarInvalidError, ArgumentError
        fail_with(package, "#{uri} gives no Last-Modified time, and its files' times cannot be read (not a tar or tar.gz)",
                  "serve it from a server that sends Last-Modified, or put it in a git repository")
      end

      def fail_with(package, message, hint)
        raise InvalidInput, [Diagnostic.error("archive-import", "#{package.name}: #{message}",
                                              location: Location.file_only(package.source_dir.to_s), hint: hint)]
      end
    end
  end
end
