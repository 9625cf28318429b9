# frozen_string_literal: true

require_relative "../names"
require_relative "../distribution"
require_relative "repository"
require_relative "../../diagnostic"

module Relspec
  module ReleaseSpec
    module Rules
      # The scalar settings and user-named entries that end up in Debian
      # package names, paths and control files.
      module Settings
        def self.call(file)
          [
            install_prefix(file), package_prefix(file), maintainer(file),
            *gems(file), gem_source(file), *selection(file), *distributions(file)
          ].compact
        end

        def self.install_prefix(file)
          prefix = file.usable("install_prefix")
          return nil if !prefix.is_a?(String) || (Names::INSTALL_PREFIX.match?(prefix) && !prefix.split("/").include?(".."))

          Diagnostic.error("install-prefix", "install_prefix #{prefix.inspect} must be an absolute path of plain names " \
                                             "(letters, digits, . _ + -), without ..",
                           location: file.location(["install_prefix"]),
                           hint: "e.g. /opt/rock; the path goes into debian/rules and shell scripts")
        end

        def self.package_prefix(file)
          prefix = file.usable("package_prefix")
          prefix.is_a?(String) ? debian_prefix(file, ["package_prefix"], prefix) : nil
        end

        def self.debian_prefix(file, path, prefix)
          return nil if Names::DEBIAN_PREFIX.match?(prefix)

          Diagnostic.error("package-prefix", "package prefix #{prefix.inspect} cannot start a Debian package name",
                           location: file.location(path), hint: "use lowercase letters, digits and . + - (e.g. rock)")
        end

        def self.maintainer(file)
          maintainer = file.usable("maintainer")
          return nil if !maintainer.is_a?(String) || Names::MAINTAINER.match?(maintainer)

          Diagnostic.error("maintainer", "maintainer #{maintainer.inspect} is not of the form \"Name <address>\"",
                           location: file.location(["maintainer"]), hint: "e.g. Rock Packaging <rock-dev@example.org>")
        end

        def self.gems(file)
          gems = file.usable("gems")
          return [] unless gems.is_a?(Hash)

          gems.flat_map do |name, version|
            problems = []
            unless Names::GEM.match?(name)
              problems << Diagnostic.error("gem-name", "#{name.inspect} is not a gem name", location: file.key_location(["gems", name]))
            end
            if version.is_a?(String) && !Names::GEM_VERSION.match?(version)
              problems << Diagnostic.error("gem-version", "version #{version.inspect} of gem #{name} is not an exact version",
                                           location: file.location(["gems", name]),
                                           hint: "gems are packaged at one exact version, e.g. \"4.0.2\"")
            end
            problems
          end
        end

        def self.selection(file)
          selection = file.usable("select")
          return [] unless selection.is_a?(Array)

          selection.each_with_index.filter_map do |name, index|
            next if !name.is_a?(String) || Names.package?(name)

            Diagnostic.error("package-name", "#{name.inspect} is not a package or metapackage name",
                             location: file.location(["select", index]),
                             hint: "autoproj names look like base/types or rock.core")
          end
        end

        def self.distributions(file)
          definitions = file.usable("distributions")
          return [] unless definitions.is_a?(Hash)

          definitions.flat_map do |codename, definition|
            unless Names::CODENAME.match?(codename)
              next [Diagnostic.error("unknown-distribution", "invalid distribution codename #{codename.inspect}",
                                     location: file.key_location(["distributions", codename]),
                                     hint: "codenames are lowercase, e.g. trixie")]
            end
            next [] unless definition.is_a?(Hash)

            [*new_distribution(file, codename, definition), *archive(file, codename, definition["archive"])]
          end
        end

        # A codename relspec does not know needs what autoproj keys it by.
        def self.new_distribution(file, codename, definition)
          return [] if Distributions::BUILTIN.key?(codename)

          %w[type labels].reject { |key| definition.key?(key) }.map do |key|
            Diagnostic.error("missing-key", "missing required key \"#{key}\" (#{codename} is not a built-in distribution)",
                             location: file.location(["distributions", codename]),
                             hint: key == "type" ? "type is ubuntu or debian" : "labels are the names autoproj knows it by, e.g. [15, duke, default]")
          end
        end

        # host: true (this machine's apt lists) stands instead of a location.
        def self.archive(file, codename, archive)
          return [] unless archive.is_a?(Hash)

          path = ["distributions", codename, "archive"]
          return Repository.check(file, path, archive, "the archive of #{codename}") unless archive["host"] == true

          located = %w[path url keyring trusted].select { |key| archive.key?(key) }
          return [] if located.empty?

          [Diagnostic.error("archive-host", "the archive of #{codename} sets host: true and #{located.join(', ')}",
                            location: file.key_location(path + ["host"]),
                            hint: "host: true reads this machine's apt lists; drop #{located.join(', ')} or host")]
        end

        # A URL (http, https, file) or a folder of .gem files, relative to the spec.
        def self.gem_source(file)
          source = file.usable("gem_source")
          return nil unless source.is_a?(String) && source.include?("://")

          Repository.bad_url(file, ["gem_source"], source, example: "https://rubygems.org, or a folder of .gem files")
        end
      end
    end
  end
end
