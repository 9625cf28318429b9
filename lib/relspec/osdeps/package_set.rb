# frozen_string_literal: true

require_relative "../yaml/writer"
require_relative "../apt/package_index"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../display_path"
require_relative "../location"
require_relative "index_check"
require_relative "release_index"
require_relative "trust"
require_relative "reader"

module Relspec
  module Osdeps
    # relspec's own autoproj package set for the releases of specs/, as
    # {relative path => content}: source.yml, init.rb (package_set/init.rb),
    # the relspec files init.rb selects with (shipped verbatim, so a
    # workspace applies a blacklist exactly as `relspec osdeps select` does),
    # and data/: the release index, each release's osdeps files and the
    # Depends/Provides of its packages per target (for the blacklist's
    # reverse dependencies, without asking apt), how apt reaches each
    # repository and the public keyring (repository.keyring) that verifies
    # each signed one.
    #
    # Everything comes from the published repositories (repository.path):
    # what users can install, not what a plan expects.
    module PackageSet
      NAME = "relspec.releases"

      INIT = File.join(__dir__, "package_set", "init.rb")
      LIB = File.expand_path("../..", __dir__)

      module_function

      # +releases+: IndexedRelease of every spec. Raises InvalidInput for a
      # release users could not install from.
      def assemble(releases)
        problems = IndexCheck.problems(releases) + releases.sort_by(&:name).flat_map { |release| problems(release) }
        raise InvalidInput, problems unless problems.empty?

        files = { "source.yml" => "name: #{NAME}\n", ".gitignore" => "/state/\n",
                  "init.rb" => File.read(INIT),
                  "data/releases.yml" => ReleaseIndex.render(releases) }
        shipped.each { |path| files["lib/#{path}"] = File.read(File.join(LIB, path)) }
        apt = {}
        releases.sort_by(&:name).each do |release|
          files.merge!(release_files(release))
          apt[release.name] = { "url" => release.url, "trusted" => release.trusted }
          next if release.trusted

          apt[release.name]["key"] = "keys/#{release.name}.gpg"
          files["data/keys/#{release.name}.gpg"] = File.binread(release.keyring)
        end
        files["data/apt.yml"] = Yaml::Writer.dump(apt)
        files.sort.to_h
      end

      # The osdeps file of each architecture and the packages of each target.
      def release_files(release)
        files = {}
        release.targets.sort.each do |codename, archs|
          archs.sort.each do |arch|
            name = "#{release.name}-#{arch}.yml"
            files["data/#{name}"] = File.read(File.join(release.repository_path, "osdeps", name))
            files["data/packages/#{release.name}/#{codename}/#{arch}.yml"] = packages(release, codename, arch)
          end
        end
        files
      end

      def packages(release, codename, arch)
        index = Apt::PackageIndex.parse(File.binread(packages_path(release, codename, arch)))
        Yaml::Writer.dump(index.entries.values.sort_by(&:name).to_h do |entry|
          [entry.name, { "depends" => entry.depends, "provides" => entry.provides }.compact]
        end)
      end

      def packages_path(release, codename, arch)
        File.join(release.repository_path, "dists", codename, "main", "binary-#{arch}", "Packages")
      end

      # What keeps users from installing +release+ through the package set.
      def problems(release)
        location = release.location("repository")
        unless release.repository_path
          return [Diagnostic.error("package-set-repository", "#{release.name} has no repository.path: the package set " \
                                                             "is made from the published repository", location: location)]
        end
        unless release.trusted || (release.keyring && File.file?(release.keyring))
          return [Diagnostic.error("package-set-trust", "#{release.name}'s repository has neither a public keyring " \
                                                        "(repository.keyring) nor trusted: true: apt would refuse it",
                                   location: location)]
        end
        if (problem = Trust.release_name(release.name) || Trust.url(release.url))
          return [Diagnostic.error("package-set-trust", "#{release.name}: #{problem}", location: location)]
        end

        release.targets.sort.flat_map do |codename, archs|
          archs.sort.flat_map do |arch|
            osdeps = File.join(release.repository_path, "osdeps", "#{release.name}-#{arch}.yml")
            next osdeps_problems(osdeps) if File.file?(packages_path(release, codename, arch)) && File.file?(osdeps)

            [Diagnostic.error("package-set-unpublished", "#{release.name} is not published for #{codename}/#{arch} " \
                                                         "in #{DisplayPath.of(release.repository_path)}",
                              location: location, hint: "run `relspec publish` for it first")]
          end
        end
      end

      # An osdeps file of a repository is data from a web server's folder
      # that users' autoproj hands to `apt-get install` as root: each entry
      # must be {type => {labels => Debian package name}} (Reader).
      def osdeps_problems(path)
        location = Location.file_only(DisplayPath.of(path))
        read = Reader.yaml(File.read(path))
        problems = read.ok? ? Reader.osdeps_problems(read.value) : [read.reason]
        problems.map { |problem| Diagnostic.error("package-set-osdeps", problem, location: location) }
      end

      # The relspec files init.rb needs, paths relative to lib/: the
      # require_relative closure of init.rb, so a require added to a shipped
      # file ships its target too (kept below lib/ so the lines still hold).
      def shipped
        seen = []
        # init.rb's lines name files below the package set's lib/
        pending = required_by(INIT).map { |target| target.delete_prefix("lib/") }
        until pending.empty?
          path = pending.shift
          next if seen.include?(path)

          seen << path
          pending.concat(required_by(File.join(LIB, path)).map do |target|
            File.expand_path(target, File.dirname(File.join(LIB, path))).delete_prefix("#{LIB}/")
          end)
        end
        seen.sort
      end

      def required_by(file)
        File.read(file).scan(/^require_relative "([^"]+)"/).map { |(target)| "#{target}.rb" }
      end
    end
  end
end
