# frozen_string_literal: true

require_relative "../debian/naming"
require_relative "../error"

module Relspec
  module Publish
    # reprepro never replaces a package by a lower version: it says
    # "Skipping inclusion … as it has already …" and exits 0. So after the
    # includes, what the target's distribution lists is compared with every
    # upload: a source package or .deb not listed at its own version stops
    # the publish (its Transaction is discarded: nothing is published),
    # naming what the repository holds instead.
    class InclusionCheck
      # One thing that was not taken: +file+ its name, +name+ the package,
      # +wanted+ the version uploaded, +held+ the versions listed instead.
      Missing = Struct.new(:source, :file, :name, :wanted, :held, keyword_init: true)

      # +listing+: [name, version, part] of the distribution (Runner#packages).
      def initialize(target, listing)
        @target = target
        @listing = listing.group_by { |name, _version, part| [name, part == "source" ? "source" : part] }
                          .transform_values { |rows| rows.map { |_name, version, _part| Debian::Naming.without_epoch(version) } }
      end

      # Raises a PublishError naming every file of +uploads+ (Upload) the
      # distribution does not list at its version.
      def check(uploads)
        missing = uploads.flat_map { |upload| missing_of(upload) }
        return if missing.empty?

        raise PublishError, message(missing)
      end

      private

      def missing_of(upload)
        wanted = [[upload.source, Debian::Naming.without_epoch(upload.version), "source", File.basename(upload.dsc)]]
        wanted += upload.debs.map do |deb|
          name, version, = File.basename(deb, ".deb").split("_")
          [name, version, @target.arch, File.basename(deb)]
        end
        wanted.filter_map do |name, version, part, file|
          held = @listing.fetch([name, part], [])
          next if held.include?(version)

          Missing.new(source: upload.source, file: file, name: name, wanted: version, held: held.sort).freeze
        end
      end

      def message(missing)
        lines = missing.map do |one|
          instead = one.held.empty? ? "it lists no #{one.name}" : "it keeps #{one.name} #{one.held.join(', ')}"
          "  #{one.file}: #{instead}"
        end
        "#{@target}: reprepro did not take #{missing.size} file(s) of #{missing.map(&:source).uniq.join(', ')}, " \
          "though it exited 0; nothing was published:\n#{lines.join("\n")}\n" \
          "reprepro never replaces a package by a lower version. Plan and compile again (relspec keeps a version " \
          "that goes down above the one published, <published>+really<new>), or remove the newer package from the " \
          "repository (reprepro remove)"
      end
    end
  end
end
