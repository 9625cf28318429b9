# frozen_string_literal: true

require "digest"
require "fileutils"
require "tmpdir"
require "zlib"
require "psych"
require "rubygems/package"
require_relative "../apt/fetcher"
require_relative "../atomic_file"
require_relative "../error"

module Relspec
  class Catalog
    # One gem of the spec's `gems:` as it is published: the .gem file (read
    # from a folder, or downloaded once from a RubyGems-style server into the
    # cache), its SHA256 and its gemspec. The .gem is the upstream source of
    # the package relspec makes from it.
    class GemArchive
      # Raised when the gem cannot be had or is not the gem asked for.
      class Problem < Relspec::Error; end

      attr_reader :name, :version, :path, :sha256, :spec, :origin

      # +source+: the spec's gem_source (an http(s)/file URL, or a folder
      # relative to +base_dir+); +cache_dir+: where downloads are kept (nil,
      # when there is no home: a folder of the user's in the system's temp).
      def self.fetch(name, version, source:, base_dir:, cache_dir:, timeout: 10)
        # Loaded here: RubyGems' package code costs 70 ms, and most releases have no gems.
        require "rubygems/package"
        file = "#{name}-#{version}.gem"
        fetcher = Apt::Fetcher.new(source, timeout: timeout)
        if fetcher.remote?
          origin = "#{source.chomp('/')}/gems/#{file}"
          # one cache folder per source: two servers may hold different files under one name
          cache_dir ||= File.join(Dir.tmpdir, "relspec-gems-#{Process.uid}")
          cache = File.join(cache_dir, Digest::SHA256.hexdigest(source.chomp("/"))[0, 16])
          path = download(fetcher, "gems/#{file}", origin, cache, file)
        else
          origin = "#{source.chomp('/')}/#{file}"
          path = File.join(File.expand_path(source.delete_prefix("file://"), base_dir), file)
          raise Problem, "gem #{name} #{version} is not in #{source} (no #{file})" unless File.file?(path)
        end
        new(name, version, path, origin)
      end

      def self.download(fetcher, relative, origin, cache_dir, file)
        cached = File.join(cache_dir, file)
        return cached if File.file?(cached)

        bytes = fetcher.fetch(relative)
        raise Problem, "#{origin} does not exist (HTTP 404)" unless bytes

        FileUtils.mkdir_p(cache_dir)
        AtomicFile.write(cached, bytes)
        cached
      rescue Apt::Fetcher::Failure => e
        raise Problem, "cannot download #{origin}: #{e.message}"
      end
      private_class_method :download

      def initialize(name, version, path, origin)
        @name = name
        @version = version
        @path = path
        @origin = origin
        @sha256 = Digest::SHA256.file(path).hexdigest
        @spec = read_spec
        freeze
      end

      # The gem's date as a catalog commit time (what dates the changelog and
      # the files of the orig tarball).
      def time
        spec.date.utc.strftime("%Y-%m-%dT%H:%M:%SZ")
      end

      def native?
        !spec.extensions.empty?
      end

      # Folders of a gem whose C/C++ headers serve only its own build.
      PRIVATE_HEADER_DIRS = %w[ext test tests spec sample samples example examples].freeze
      HEADER = /[.](h|hh|hpp|hxx|ipp)\z/

      # True for a gem with a C extension that also installs headers for
      # other code to compile against (Rice: rice/*.hpp, which include
      # ruby.h): what builds against it needs Ruby's headers too.
      def ships_headers?
        native? && spec.files.any? do |file|
          file.match?(HEADER) && !PRIVATE_HEADER_DIRS.include?(file.split("/").first)
        end
      end

      # The gemspec's required_ruby_version (a Gem::Requirement, ">= 0" when
      # it sets none).
      def required_ruby
        spec.required_ruby_version || Gem::Requirement.default
      end

      # Runtime dependencies: [[name, requirement]].
      def runtime_dependencies
        spec.runtime_dependencies.map { |dependency| [dependency.name, dependency.requirement] }.sort_by(&:first)
      end

      # Unpacks the gem into +dir+ as gem2tgz does: the files of the gem,
      # and its metadata as metadata.yml (the bytes the gem holds, so the
      # tree does not depend on the local RubyGems version).
      def unpack(dir)
        Gem::Package.new(path).extract_files(dir)
        File.binwrite(File.join(dir, "metadata.yml"), metadata_bytes)
      rescue Gem::Exception, Zlib::Error => e
        raise Problem, "cannot unpack #{File.basename(path)}: #{e.message}"
      end

      private

      def read_spec
        spec = Gem::Package.new(path).spec
        return spec if spec.name == name && spec.version.to_s == version

        raise Problem, "#{origin} holds #{spec.name} #{spec.version}, not #{name} #{version}"
      rescue Gem::Exception, Zlib::Error, Psych::Exception, ArgumentError => e
        raise Problem, "#{origin} is not a readable gem (#{e.message})"
      end

      def metadata_bytes
        File.open(path, "rb") do |io|
          Gem::Package::TarReader.new(io).each do |entry|
            return Zlib.gunzip(entry.read) if entry.full_name == "metadata.gz"
          end
        end
        raise Problem, "#{File.basename(path)} has no metadata.gz"
      end
    end
  end
end
