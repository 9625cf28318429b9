# frozen_string_literal: true

require "digest"
require "open3"
require "zlib"
require "stringio"
require_relative "fetcher"
require_relative "cache"
require_relative "signature"
require_relative "release_file"
require_relative "package_index"
require_relative "../printable"

module Relspec
  module Apt
    # Reads an apt repository (a reprepro base folder or its URL): the
    # Release file of a codename, checked against a keyring unless the
    # repository is trusted as it is, and the Packages index of one
    # architecture, verified against the SHA256 the Release file gives.
    class Repository
      # Any problem reading the repository; the message names the URL.
      class Error < Relspec::RepositoryError; end

      # The repository has no such codename, or no index for that
      # architecture: for a release's own repository that only means nothing
      # was published there yet.
      class Missing < Error; end

      # InRelease/Release of the largest archives (Ubuntu, Debian) are below
      # 300 KiB, their signatures below 10 KiB: a server sending more is not
      # serving a Release file (docs/limits.md).
      MAX_RELEASE_BYTES = 16 * 1024 * 1024
      MAX_SIGNATURE_BYTES = 1024 * 1024

      COMPRESSIONS = [["Packages.xz", :xz], ["Packages.gz", :gzip], ["Packages", :none]].freeze
      # How long a remote index that does not match the Release file is left
      # before it is read the one more time.
      RETRY_PAUSE = 1.0

      attr_reader :fetcher

      # +clock+ gives the current time, against which Valid-Until is checked.
      # +retry_pause+: seconds before a mismatching index is read again.
      def initialize(fetcher, keyring: nil, trusted: false, cache: Cache.new(nil), clock: -> { Time.now },
                     retry_pause: RETRY_PAUSE)
        @clock = clock
        @retry_pause = retry_pause
        @fetcher = fetcher
        @keyring = keyring
        @trusted = trusted
        @cache = cache
        @releases = {}
      end

      def url
        fetcher.base
      end

      def release(codename)
        @releases[codename] ||= read_release(codename)
      end

      # The architectures whose Packages indices apt reads for +arch+ in
      # +codename+ (ReleaseFile#package_architectures): what every reader of
      # a distribution's packages reads, so that an Architecture: all
      # package is found where apt finds it.
      def index_architectures(codename, arch, component: "main")
        release(codename).package_architectures(arch, component: component)
      end

      # The Packages index of +codename+/+component+/+arch+.
      def packages(codename, arch, component: "main")
        text, where = verified_index(codename, arch, component)
        PackageIndex.parse(text)
      rescue Deb822::ParseError, PackageIndex::Invalid => e
        raise Error, "#{where}: malformed index: #{e.message}"
      end

      # The same index as verified, uncompressed text (for readers that need
      # other fields than PackageIndex keeps).
      def packages_text(codename, arch, component: "main")
        verified_index(codename, arch, component).first
      end

      # What identifies the content of that index without parsing it: the
      # SHA256 of the file #packages reads, the first form the Release file
      # lists that is present (not merely the first listed: a mirror may
      # list a Packages.xz it dropped while it updates the .gz). Raises
      # Missing like #packages; the bytes are kept for #packages.
      #
      # The digest of every form the Release file lists for that index
      # (path, SHA256, size of Packages.xz, .gz and plain): whichever of them
      # is read, it changes with it, and nothing but the Release file is
      # downloaded to know it (a mirror that lists an absent .xz before the
      # .gz it updates still gets a new key).
      def index_digest(codename, arch, component: "main")
        release = release(codename)
        listed = listed_indices(release, codename, arch, component).map do |path, _|
          checksum = release.checksum(path)
          "#{path} #{checksum.sha256} #{checksum.size}\n"
        end
        Digest::SHA256.hexdigest(listed.join)
      end

      # The bytes of +path+ below dists/+codename+ (any file its Release
      # file lists), checked against the size and SHA256 listed there; an
      # index compressed with gzip or xz, uncompressed. Raises Error when
      # it is not listed, missing or not what the Release file says.
      def listed_text(codename, path)
        release = release(codename)
        where = "#{url}/dists/#{codename}/#{path}"
        raise Error, "#{where} is not listed in the Release file" unless release.checksum(path)

        kind = COMPRESSIONS.find { |file, _| path.end_with?("/#{file}") }&.last || :none
        decompress(index_bytes(codename, release, path), kind, where)
      end

      private

      # [text, where it was read]
      def verified_index(codename, arch, component)
        release = release(codename)
        path, kind, bytes = present_index(codename, release, listed_indices(release, codename, arch, component))
        where = "#{url}/dists/#{codename}/#{path}"
        [decompress(bytes, kind, where), where]
      end

      # [[path, compression]] the Release file lists for that index, in the
      # order they are tried.
      def listed_indices(release, codename, arch, component)
        directory = "#{component}/binary-#{arch}"
        listed = COMPRESSIONS.map { |file, kind| ["#{directory}/#{file}", kind] }.select { |path, _| release.checksum(path) }
        return listed unless listed.empty?

        raise Missing, "#{url}/dists/#{codename}/Release lists no #{directory}/Packages index " \
                       "(architectures: #{Printable.text(release.architectures.join(' '))})"
      end

      def read_release(codename)
        base = "dists/#{codename}"
        in_release = @fetcher.fetch("#{base}/InRelease", max_bytes: MAX_RELEASE_BYTES)
        text, raw =
          if in_release
            [clearsigned_content(in_release, "#{url}/#{base}/InRelease"), in_release]
          else
            plain = @fetcher.fetch("#{base}/Release", max_bytes: MAX_RELEASE_BYTES)
            raise Missing, "#{url} has no distribution #{codename} (no #{base}/InRelease or Release)" unless plain

            [detached_content(plain, base), plain]
          end
        check_release(ReleaseFile.parse(text, raw: raw), codename, base)
      rescue Fetcher::Failure => e
        raise Error, e.message
      rescue Deb822::ParseError, ArgumentError, TypeError => e
        raise Error, "#{url}/#{base}: malformed Release file: #{e.message}"
      end

      def check_release(release, codename, base)
        unless release.describes?(codename)
          raise Error, "#{url}/#{base}: the Release file is of " \
                       "#{Printable.text([release.codename, release.suite].compact.uniq.join('/'))}, " \
                       "not #{codename} (a Release file served under another distribution's name is refused)"
        end
        if release.expired?(@clock.call)
          raise Error, "#{url}/#{base}: the Release file expired on " \
                       "#{release.valid_until.strftime('%Y-%m-%d %H:%M:%S UTC')} (Valid-Until); the repository must " \
                       "be exported again"
        end
        release
      end

      def clearsigned_content(bytes, where)
        return Signature.unarmor(bytes) if @trusted && !@keyring
        raise Error, "#{where} cannot be verified: no keyring given (set keyring:, or trusted: true)" unless @keyring

        Signature.verify_clearsigned(bytes, @keyring).force_encoding(Encoding::UTF_8)
      rescue Signature::Invalid => e
        raise Error, "#{where}: signature check failed: #{e.message}"
      end

      def detached_content(content, base)
        return content.force_encoding(Encoding::UTF_8) if @trusted && !@keyring
        raise Error, "#{url}/#{base}/Release is unsigned: set keyring:, or trusted: true" unless @keyring

        signature = @fetcher.fetch("#{base}/Release.gpg", max_bytes: MAX_SIGNATURE_BYTES)
        raise Error, "#{url}/#{base}/Release has no Release.gpg signature" unless signature
        raise Error, "#{url}/#{base}/Release.gpg is empty: the repository must be signed again" if signature.empty?

        Signature.verify_detached(content, signature, @keyring).force_encoding(Encoding::UTF_8)
      rescue Signature::Invalid => e
        raise Error, "#{url}/#{base}/Release: signature check failed: #{e.message}"
      end

      # The first present index of +listed+, read once per Release file.
      def present_index(codename, release, listed)
        @present ||= {}
        @present[[codename, release.sha256, listed]] ||= first_present(codename, release, listed)
      end

      # Mirrors often drop Packages.xz while their Release still lists it:
      # the next form the Release lists is read instead (each is checked
      # against its own checksum). Only when none is there is it an error.
      def first_present(codename, release, listed)
        missing = nil
        listed.each do |path, kind|
          return [path, kind, index_bytes(codename, release, path)]
        rescue MissingIndex => e
          missing ||= e
        end
        raise Error, missing.message
      end

      class MissingIndex < Error; end
      private_constant :MissingIndex

      def index_bytes(codename, release, path)
        checksum = release.checksum(path)
        unless checksum.valid?
          raise Error, "#{url}/dists/#{codename}/Release: the SHA256 of #{path} is not 64 hex digits " \
                       "(#{Printable.text(checksum.sha256[0, 80])}): a malformed Release file"
        end
        cached = @fetcher.remote? ? @cache.read(release.sha256, "#{codename}/#{path}") : nil
        return cached if cached && Digest::SHA256.hexdigest(cached) == checksum.sha256

        bytes = matching_bytes(codename, release, path)
        @cache.write(release.sha256, "#{codename}/#{path}", bytes) if @fetcher.remote?
        bytes
      rescue Fetcher::Failure => e
        raise Error, e.message
      end

      # The bytes of +path+ that match the Release file. A mismatch is read
      # once more after RETRY_PAUSE (the index may have been replaced
      # between the Release file and it); one that remains is the archive's
      # state, said as apt says it.
      def matching_bytes(codename, release, path)
        checksum = release.checksum(path)
        _, bytes = index_download(codename, release, path)
        return bytes if matches?(bytes, checksum)

        sleep(@retry_pause) if @fetcher.remote?
        where, bytes = index_download(codename, release, path)
        return bytes if matches?(bytes, checksum)

        raise Error, "#{where} does not match the SHA256 of the Release file (#{mismatch(bytes, checksum)}), " \
                     "also when read again: the archive may be in the middle of an update (mirror sync in " \
                     "progress?); try again later, or use another mirror"
      end

      # [where, bytes] of +path+: by its digest where the Release file
      # offers that (apt's Acquire-By-Hash), else, or when the mirror lacks
      # that file, by its name.
      def index_download(codename, release, path)
        checksum = release.checksum(path)
        if release.by_hash?
          hashed = "dists/#{codename}/#{File.dirname(path)}/by-hash/SHA256/#{checksum.sha256}"
          bytes = @fetcher.fetch(hashed, max_bytes: checksum.size)
          return [@fetcher.url_of(hashed), bytes] if bytes
        end
        where = "#{url}/dists/#{codename}/#{path}"
        # the Release file says how large the index is: never read past that
        bytes = @fetcher.fetch("dists/#{codename}/#{path}", max_bytes: checksum.size)
        raise MissingIndex, "#{where} is listed in the Release file but missing" unless bytes

        [where, bytes]
      end

      def matches?(bytes, checksum)
        bytes.bytesize == checksum.size && Digest::SHA256.hexdigest(bytes) == checksum.sha256
      end

      def mismatch(bytes, checksum)
        return "got #{bytes.bytesize} bytes, expected #{checksum.size}" unless bytes.bytesize == checksum.size

        "got SHA256 #{Digest::SHA256.hexdigest(bytes)}, expected #{checksum.sha256}"
      end

      def decompress(bytes, kind, where)
        text =
          case kind
          # every gzip member, as gzip -d does (GzipReader alone stops after the first)
          when :gzip then Zlib::GzipReader.zcat(StringIO.new(bytes))
          when :xz then xz_decompress(bytes, where)
          else bytes
          end
        text.force_encoding(Encoding::BINARY)
      rescue Zlib::Error => e
        raise Error, "#{where}: corrupt gzip data: #{e.message}"
      end

      def xz_decompress(bytes, where)
        out, err, status = Open3.capture3("xz", "-dc", stdin_data: bytes, binmode: true)
        raise Error, "#{where}: corrupt xz data: #{err.strip}" unless status.success?

        out
      end
    end
  end
end
