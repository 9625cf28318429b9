# frozen_string_literal: true

require_relative "../yaml/located_document"
require_relative "../apt/version"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../output_tree"

module Relspec
  module Publish
    # <out>/<release>/<codename>-<arch>/build-results.yml, what `relspec
    # build` records per target, read as strictly as the lock: every key
    # known, every value of its type, every path inside the target folder.
    # A damaged file is an InvalidInput naming file:line, never "nothing
    # built": publishing from a guess could put the wrong bytes into a
    # repository, where they stay forever.
    class BuildResults
      FORMAT_KEY = "relspec_build_results"
      FORMAT_VERSION = 1
      FILE_NAME = "build-results.yml"
      ROOT_KEYS = [FORMAT_KEY, "release", "target", "backend", "packages"].freeze
      PACKAGE_KEYS = %w[package version status duration log reason files].freeze
      FILE_KEYS = %w[name sha256 size].freeze
      STATUSES = %w[built failed skipped published].freeze
      SHA256 = /\A[0-9a-f]{64}\z/
      SOURCE_NAME = /\A[a-z0-9][a-z0-9.+-]+\z/
      HINT = "build-results.yml is written by `relspec build`: run it again for this target"

      # One produced file, relative to the target folder.
      Produced = Struct.new(:name, :sha256, :size, keyword_init: true)

      # One source package's result. +files+: Produced, empty unless built.
      Entry = Struct.new(:source, :package, :version, :status, :files, keyword_init: true) do
        def built?
          status == "built"
        end
      end

      attr_reader :path, :release, :target, :entries

      def self.path(out, release, target)
        OutputTree.new(out, release).results_file(target)
      end

      # The results at +path+, for +release+ and +target+ (a Target).
      def self.read(path, release:, target:)
        new(Yaml::LocatedDocument.load(path), release, target)
      end

      def self.parse(text, file:, release:, target:)
        new(Yaml::LocatedDocument.parse(text, file: file), release, target)
      end

      def initialize(document, release, target)
        @document = document
        @path = document.file
        @release = release
        @target = target.to_s
        @entries = read.freeze
        freeze
      end

      def built
        entries.select(&:built?)
      end

      private

      def read
        unless @document.ok?
          raise InvalidInput, @document.diagnostics.select(&:error?).map { |d| diagnostic(d.message, d.location) }
        end

        data = @document.data
        fail_at([], "the file is empty or not a mapping") unless data.is_a?(Hash)
        fail_at([FORMAT_KEY], "unknown format #{data[FORMAT_KEY].inspect} (this relspec reads #{FORMAT_VERSION})") \
          unless data[FORMAT_KEY] == FORMAT_VERSION
        known_keys(data, [], ROOT_KEYS)
        expect(data, ["release"], @release)
        expect(data, ["target"], @target)
        text(data, ["backend"])
        packages = mapping(data, ["packages"])
        packages.map { |source, record| entry(source, record) }.sort_by(&:source)
      end

      def entry(source, record)
        path = ["packages", source]
        fail_at(path, "#{source.inspect} is not a Debian source package name") unless source.to_s.match?(SOURCE_NAME)
        fail_at(path, "packages.#{source} must be a mapping") unless record.is_a?(Hash)
        known_keys(record, path, PACKAGE_KEYS)
        status = text(record, path + ["status"])
        fail_at(path + ["status"], "status #{status.inspect} is not one of #{STATUSES.join(', ')}") unless STATUSES.include?(status)
        files = record["files"].nil? ? [] : files(record["files"], path + ["files"])
        fail_at(path + ["files"], "a built package lists the files it produced") if status == "built" && files.empty?
        Entry.new(source: source, package: text(record, path + ["package"]), version: version(record, path + ["version"]),
                  status: status, files: files.freeze).freeze
      end

      def files(list, path)
        fail_at(path, "#{describe(path)} must be a list") unless list.is_a?(Array)
        list.each_with_index.map do |file, index|
          at = path + [index]
          fail_at(at, "#{describe(at)} must be a mapping of name, sha256 and size") unless file.is_a?(Hash)
          known_keys(file, at, FILE_KEYS)
          name = text(file, at + ["name"])
          fail_at(at + ["name"], "file #{name.inspect} is not a plain path inside the target folder") unless inside?(name)
          sha256 = text(file, at + ["sha256"])
          fail_at(at + ["sha256"], "sha256 must be 64 lowercase hex digits") unless sha256.match?(SHA256)
          size = file["size"]
          fail_at(at + ["size"], "size must be a number of bytes") unless size.is_a?(Integer) && size >= 0
          Produced.new(name: name, sha256: sha256, size: size).freeze
        end
      end

      # Names from a file become paths: no absolute path, no "..", no empty part.
      def inside?(name)
        !name.start_with?("/") && name.split("/").none? { |part| part.empty? || part == "." || part == ".." }
      end

      def version(hash, path)
        value = @document.raw(path) || text(hash, path)
        Apt::Version.parse(value)
        value
      rescue ArgumentError
        fail_at(path, "invalid Debian version #{value.inspect}")
      end

      def expect(hash, path, wanted)
        value = text(hash, path)
        fail_at(path, "#{describe(path)} is #{value.inspect}, expected #{wanted.inspect}") unless value == wanted
      end

      def mapping(hash, path)
        value = hash[path.last]
        return {} if value.nil?
        fail_at(path, "#{describe(path)} must be a mapping") unless value.is_a?(Hash)

        value
      end

      def text(hash, path)
        value = hash[path.last]
        fail_at(path, "#{describe(path)} is missing") if value.nil?
        fail_at(path, "#{describe(path)} must be text") unless value.is_a?(String) || value.is_a?(Numeric)

        value.to_s
      end

      def known_keys(hash, path, keys)
        unknown = hash.keys - keys
        fail_at(path + [unknown.first], "unknown key #{unknown.first.inspect} in #{describe(path)}") unless unknown.empty?
      end

      def describe(path)
        path.empty? ? "the file" : path.join(".")
      end

      def fail_at(path, message)
        raise InvalidInput, [diagnostic(message, @document.location(path))]
      end

      def diagnostic(message, location)
        Diagnostic.error("build-results", "cannot read the build results: #{message}", location: location, hint: HINT)
      end
    end
  end
end
