# frozen_string_literal: true

require "yaml"
require_relative "../atomic_file"
require_relative "../error"
require_relative "../frozen"
require_relative "../target"
require_relative "../osdeps/trust"
require_relative "../yaml/located_document"
require_relative "../yaml/field_reader"

module Relspec
  module Mirror
    # A folder given to `relspec mirror verify` is not a mirror relspec made.
    class NotAMirror < RepositoryError; end

    # A mirror's mirror.yml: the release, the file name of its public key
    # and, per target, the release's package names (what the dynamic proof
    # installs). `relspec mirror` writes it; `relspec mirror verify` reads it
    # from a disk that travelled, so as untrusted input: every value must be
    # what relspec writes (package names by the package set's one Debian
    # name rule, Osdeps::Trust), else it is refused at its line before
    # anything reads the mirror or runs apt.
    class Manifest
      FILE = "mirror.yml"
      HINT = "mirror.yml is written by relspec mirror: make the mirror again with relspec mirror SPEC --out DIR"
      # What a Target's parts may be when they come from a file: they
      # become paths of the mirror (dists/<codename>/…/binary-<arch>).
      PART = /\A[a-z0-9][a-z0-9.-]*\z/

      attr_reader :release, :key, :targets

      # +targets+: Target => the release's package names (sorted).
      def initialize(release:, key:, targets:)
        @release = release
        @key = key
        @targets = targets.sort_by { |target, _| target.to_s }.to_h { |target, names| [target, Frozen.deep(names)] }.freeze
        freeze
      end

      # The manifest of the mirror in +dir+; NotAMirror without one,
      # InvalidInput (file:line) for a value relspec would not write.
      def self.read(dir)
        path = File.join(dir, FILE)
        unless File.exist?(path)
          raise NotAMirror, "#{dir} is not a mirror: it has no #{FILE} (make one with relspec mirror SPEC --out #{dir})"
        end

        Reader.new(Yaml::LocatedDocument.load(path)).manifest
      end

      def write(dir)
        data = { "release" => release, "key" => key,
                 "targets" => targets.to_h { |target, names| [target.to_s, { "release" => names.dup }] } }
        AtomicFile.write(File.join(dir, FILE), YAML.dump(data.compact))
      end

      # The strict reading of one mirror.yml.
      class Reader
        attr_reader :manifest

        def initialize(document)
          @fields = Yaml::FieldReader.new(document, rule: "mirror-manifest", what: FILE, hint: HINT)
          data = @fields.root
          @fields.known_keys(data, [], %w[release key targets])
          release = checked(data, ["release"]) { |name| Osdeps::Trust.release_name(name) }
          key = data["key"].nil? ? nil : key(data, release)
          @manifest = Manifest.new(release: release, key: key, targets: targets(data))
        end

        private

        # relspec names the key after the release, beside mirror.yml: a
        # path anywhere else would make apt trust that file.
        def key(data, release)
          checked(data, ["key"]) do |name|
            "the key #{name.inspect} is not #{release}-mirror.asc" unless name == "#{release}-mirror.asc"
          end
        end

        def targets(data)
          targets = @fields.mapping(data, ["targets"])
          @fields.fail_at(["targets"], "targets lists no target") if targets.empty?
          targets.to_h do |name, entry|
            path = ["targets", name]
            [target(name, path), names(entry, path)]
          end
        end

        def target(name, path)
          codename, arch = name.to_s.split("/", 2)
          @fields.fail_at(path, "#{name.inspect} is not a target name") unless [codename, arch].all? { |part| PART.match?(part.to_s) }
          Target.new(codename, arch).freeze
        end

        def names(entry, path)
          @fields.fail_at(path, "#{@fields.describe(path)} must be a mapping of release") unless entry.is_a?(Hash)
          @fields.known_keys(entry, path, %w[release])
          @fields.list(entry, path + ["release"], of: "package names").each_index.map do |index|
            checked(entry["release"], path + ["release", index]) { |name| Osdeps::Trust.debian_name(name) }
          end
        end

        # The value at +path+ (its last step a key of +container+), refused
        # with the block's reason when it gives one.
        def checked(container, path)
          value = container[path.last]
          reason = yield(value)
          @fields.fail_at(path, reason) if reason
          value
        end
      end
    end
  end
end
