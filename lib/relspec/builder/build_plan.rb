# frozen_string_literal: true

require_relative "../atomic_file"
require_relative "../display_path"
require_relative "../error"
require_relative "../output_tree"
require_relative "../debian_name"
require_relative "../apt/version"
require_relative "../yaml/field_reader"
require_relative "../yaml/located_document"
require_relative "../yaml/writer"

module Relspec
  module Builder
    # One target's plan.yml: the source packages to build in dependency
    # order, each with the sources of the same release it needs built first.
    # Packages the release's repository already holds at their version are
    # not in it (compile decided "published" for them). One class holds the
    # writer (`relspec compile`) and the strict reader (`relspec build`):
    # every key known, every value of its type, names that become paths
    # checked, build-dependencies only on sources listed before; a damaged
    # file is an InvalidInput naming file:line.
    class BuildPlan
      FILE = OutputTree::PLAN_FILE
      ROOT_KEYS = %w[release target builds].freeze
      BUILD_KEYS = %w[package source version dsc build_depends cutoff].freeze
      CUTOFF_KEYS = %w[keeps because debian_digest against].freeze
      HINT = "plan.yml is written by `relspec compile`: run it again"

      # +cutoff+: a Cutoff when the plan names the build an early cutoff
      # candidate (Plan::CutoffCandidate), else nil.
      Entry = Struct.new(:package, :source, :version, :dsc, :build_depends, :cutoff, keyword_init: true) do
        def to_h
          { "package" => package, "source" => source, "version" => version, "dsc" => dsc, "build_depends" => build_depends,
            "cutoff" => cutoff&.to_h }.compact
        end
      end

      # The published version a candidate keeps (+keeps+), the sources
      # whose new builds moved it (+because+) and the digest of its debian/
      # once kept with its candidate dependencies (+debian_digest+,
      # Plan::CutoffCandidate; nil in plans written before it) and the
      # version the repository holds of each build of its closure, source =>
      # Debian version (+against+: what the kept build was made against;
      # nil or empty in plans written before it: unknown), docs/abi.md.
      Cutoff = Struct.new(:keeps, :because, :debian_digest, :against, keyword_init: true) do
        def to_h
          { "keeps" => keeps, "because" => because, "debian_digest" => debian_digest,
            "against" => against.nil? || against.empty? ? nil : against }.compact
        end
      end

      attr_reader :dir, :release, :target, :entries

      # The sources of +entries+ (source => Entry, in plan order) that
      # +source+ needs built first, directly or through others, in plan
      # order (dependencies first): what its build installs, and what the
      # early cutoff goes by (docs/abi.md).
      def self.closure(entries, source)
        seen = {}
        pending = [source]
        until pending.empty?
          (entries[pending.pop]&.build_depends || []).each do |need|
            pending << need unless seen[need]
            seen[need] = true
          end
        end
        entries.keys.select { |one| seen[one] }
      end

      # Writes +entries+ (Entry) as <dir>/plan.yml when its text changed;
      # true when it did.
      def self.write(dir, release:, target:, entries:)
        text = Yaml::Writer.dump("release" => release, "target" => target.to_s, "builds" => entries.map(&:to_h))
        AtomicFile.update(File.join(dir, FILE), text)
      end

      # +dir+: <out>/<release>/<codename>-<arch>.
      def self.read(dir)
        path = File.join(dir, FILE)
        shown = DisplayPath.of(path)
        raise BuildError, "#{shown} does not exist: run `relspec compile` first" unless File.exist?(path)

        new(dir, Yaml::LocatedDocument.load(shown))
      end

      def self.parse(text, dir:)
        new(dir, Yaml::LocatedDocument.parse(text, file: File.join(dir, FILE)))
      end

      def initialize(dir, document)
        @dir = dir
        @fields = Yaml::FieldReader.new(document, rule: "build-plan", what: "the build plan", hint: HINT)
        data = @fields.root
        @fields.known_keys(data, [], ROOT_KEYS)
        @release = @fields.text(data, ["release"])
        @target = @fields.text(data, ["target"])
        @fields.fail_at(["target"], "target #{@target.inspect} is not codename/arch") unless @target.match?(%r{\A[^/]+/[^/]+\z})
        @entries = builds(data).freeze
        remove_instance_variable(:@fields)
        freeze
      end

      def codename
        target.split("/").first
      end

      def arch
        target.split("/").last
      end

      def dsc_path(entry)
        File.join(dir, entry.dsc)
      end

      private

      def builds(data)
        seen = {}
        @fields.list(data, ["builds"], of: "builds").each_with_index.map do |build, index|
          path = ["builds", index]
          @fields.fail_at(path, "builds.#{index} must be a mapping") unless build.is_a?(Hash)
          @fields.known_keys(build, path, BUILD_KEYS)
          entry(build, path, seen).tap { |made| seen[made.source] = true }
        end
      end

      def entry(build, path, seen)
        source = @fields.text(build, path + ["source"])
        # source names become folder names (results/<source>, logs/<source>.log)
        @fields.fail_at(path + ["source"], "invalid source name #{source.inspect}") unless DebianName.valid?(source)
        @fields.fail_at(path + ["source"], "#{source} is listed twice") if seen[source]
        version = @fields.text(build, path + ["version"])
        @fields.fail_at(path + ["version"], "invalid Debian version #{version.inspect}") unless Apt::Version.valid?(version)
        needs = @fields.list(build, path + ["build_depends"], of: "source names").each_with_index.map do |need, at|
          @fields.fail_at(path + ["build_depends", at], "#{need.inspect} is not a source listed before #{source}") \
            unless need.is_a?(String) && seen[need]
          need
        end
        Entry.new(package: @fields.text(build, path + ["package"]), source: source, version: version,
                  dsc: @fields.plain_path(build, path + ["dsc"]), build_depends: needs.freeze,
                  cutoff: cutoff(build, path + ["cutoff"], needs)).freeze
      end

      def cutoff(build, path, needs)
        data = build[path.last]
        return nil if data.nil?

        @fields.fail_at(path, "#{@fields.describe(path)} must be a mapping of keeps and because") unless data.is_a?(Hash)
        @fields.known_keys(data, path, CUTOFF_KEYS)
        keeps = @fields.text(data, path + ["keeps"])
        @fields.fail_at(path + ["keeps"], "invalid Debian version #{keeps.inspect}") unless Apt::Version.valid?(keeps)
        because = @fields.list(data, path + ["because"], of: "source names").each_with_index.map do |source, at|
          @fields.fail_at(path + ["because", at], "#{source.inspect} is not among the build's build_depends") \
            unless needs.include?(source)
          source
        end
        digest = data["debian_digest"].nil? ? nil : @fields.text(data, path + ["debian_digest"])
        @fields.fail_at(path + ["debian_digest"], "debian_digest must be 64 lowercase hex digits") \
          unless digest.nil? || digest.match?(/\A[0-9a-f]{64}\z/)
        Cutoff.new(keeps: keeps, because: because.freeze, debian_digest: digest,
                   against: against(data, path + ["against"])).freeze
      end

      # source => the Debian version the repository holds (Cutoff).
      def against(data, path)
        @fields.mapping(data, path).to_h do |source, version|
          @fields.fail_at(path + [source], "invalid source name #{source.inspect}") \
            unless source.is_a?(String) && DebianName.valid?(source)
          held = @fields.text(data[path.last], path + [source])
          @fields.fail_at(path + [source], "invalid Debian version #{version.inspect}") unless Apt::Version.valid?(held)
          [source.freeze, held.freeze]
        end.freeze
      end
    end
  end
end
