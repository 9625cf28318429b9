# frozen_string_literal: true

require "digest"
require_relative "release_specs"
require_relative "error"
require_relative "target"
require_relative "output_tree"
require_relative "target_build"
require_relative "builder/abi_dumper"
require_relative "abi/published_dumps"
require_relative "abi/comparison"
require_relative "abi/report"

module Relspec
  # `relspec abi SPEC`: for every shared library the release builds, the
  # verdict of its ABI against the same package in the nearest ancestor
  # that published a dump of it (or in the release +against+ names: an
  # ancestor or the release itself, i.e. its published version). The
  # release's own dumps are those of its last build (<out>), else those its
  # repository publishes. docs/abi.md.
  module Abi
    # One dump on this side of the comparison.
    Side = Struct.new(:package, :library, :file, :sha256, keyword_init: true) do
      # The dump's bytes as recorded (build-results.yml or the index), else
      # an error: a dump changed since it was made is not compared.
      def verified
        raise ToolError, "the ABI dump #{file} is missing" unless File.file?(file)

        actual = Digest::SHA256.file(file).hexdigest
        raise ToolError, "the ABI dump #{file} has changed since it was recorded (sha256 #{actual}, recorded #{sha256})" \
          unless actual == sha256

        file
      end
    end

    def self.run(path, out:, target: nil, against: nil)
      resolution = ReleaseSpec.resolve(path)
      effective = resolution.effective
      tree = OutputTree.new(out, effective.release)
      builds = Target.select(target, Target.all(effective), effective.release).map { |one| TargetBuild.read(tree, one) }
      of(resolution, builds, against: against)
    end

    # The Report of a release already read: +resolution+ of its spec and
    # +builds+, the TargetBuild of each target to compare.
    def self.of(resolution, builds, against: nil)
      release = resolution.effective.release
      lineage = resolution.lineage
      targets = builds.map do |build|
        repositories = published_by(lineage)
        counterparts = counterparts(repositories, release, against)
        Report::TargetReport.new(target: build.target, entries: compare(own(build, repositories.first, release),
                                                                        counterparts, build.target).freeze).freeze
      end
      Report.new(release: release, targets: targets.freeze).freeze
    end

    # Where a release publishes: +name+, +uri+ (its repository's location).
    Publisher = Struct.new(:name, :uri, keyword_init: true)

    # The members of +lineage+ (ReleaseSpec::Lineage) that publish
    # somewhere, own release first: [Publisher]. The ABI reads their
    # dumps, not their packages, so no suite or keyring is needed.
    def self.published_by(lineage)
      lineage.filter_map do |member|
        uri = member.repository&.location
        uri && Publisher.new(name: member.name, uri: uri).freeze
      end
    end

    # The release's own dumps: its last build's (at the planned versions),
    # else its published ones.
    def self.own(build, own_repository, release)
      if build.built?
        return build.results.built.flat_map do |record|
          record.files.filter_map do |file|
            library = Builder::AbiDumper.library_of(file.name)
            library && Side.new(package: record.package, library: library, file: File.join(build.dir, file.name),
                                sha256: file.sha256).freeze
          end
        end
      end
      return [] unless own_repository&.name == release

      published(own_repository.uri, build.target)
    end

    def self.published(repository, target)
      PublishedDumps.read(repository, target).entries.map do |entry|
        Side.new(package: entry.package, library: entry.library, file: entry.file, sha256: entry.sha256).freeze
      end
    end

    # The repositories to look in, nearest first: the ancestors', or the
    # one of +against+ (an ancestor or the release itself).
    def self.counterparts(repositories, release, against)
      return repositories.reject { |repository| repository.name == release } unless against

      chosen = repositories.select { |repository| repository.name == against }
      return chosen unless chosen.empty?

      names = repositories.map(&:name).join(", ")
      raise InvalidOption, "--against #{against}: not #{release} or one of its ancestors with a repository (#{names})"
    end

    def self.compare(sides, repositories, target)
      indexes = repositories.to_h { |repository| [repository.name, published(repository.uri, target)] }
      sides.sort_by { |side| [side.package, side.library] }.map do |side|
        release, old = indexes.lazy.map do |name, dumps|
          [name, dumps.find { |dump| dump.package == side.package && dump.library == side.library }]
        end.find { |_, dump| dump }
        verdict = old && Comparison.compare(old.verified, side.verified)
        Report::Entry.new(package: side.package, library: side.library, against: release, verdict: verdict).freeze
      end
    end
    private_class_method :own, :published, :counterparts, :compare
  end
end
