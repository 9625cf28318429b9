# frozen_string_literal: true

require "yaml"
require "fileutils"
require "open3"
require_relative "../operating_system"
require_relative "../blacklist_reading"
require_relative "../selection"
require_relative "../reader"
require_relative "refusal"
require_relative "apt_sources"
require_relative "environment"

# relspec's package set in a user's workspace (init.rb, on every autoproj
# command).
module RelspecPackageSet
  Index = Struct.new(:entries)
  Entry = Struct.new(:name, :depends, :provides)
  BlacklistEntry = Struct.new(:pattern, :location)

  # What this workspace runs on: autoproj's names, the Debian architecture,
  # the codename.
  System = Struct.new(:os, :arch, :codename) do
    def to_s
      "#{os.names.join(',')} #{os.versions.reject { |version| version == 'default' }.join(',')} (#{arch})"
    end
  end

  # The release chosen in autoproj/relspec.yml, its packages for this
  # system as autoproj's OS packages, apt pointed at its repositories, the
  # installed packages' env.yml in the environment. Everything is read and
  # checked before apt, /etc/apt or the environment see any of it.
  class Activation
    def initialize(ws, dir)
      @ws = ws
      @dir = dir
      @data = File.join(dir, "data")
    end

    def run
      release = chosen_release
      system = this_system
      lineage = lineage(release)
      mapping = mapping(lineage, system)
      sources = AptSources.new(@data, lineage, system.codename, File.join(@dir, "state"))
      selection = Relspec::Osdeps::Selection.new(mapping, indices(lineage, system), blacklist)
      environment = Environment.read(lineage, selection.active.values)
      # everything read is checked: only now apt, /etc/apt and the
      # environment see any of it
      record(release, selection)
      @ws.os_package_resolver.merge(
        Autoproj::OSPackageResolver.new(selection.active.transform_values { |deb| { "default" => deb } },
                                        File.join(@dir, "state", "relspec.osdeps"))
      )
      sources.install(refresh: updating?)
      sources.upgrade(selection.active.values.uniq.sort) if updating?
      environment.apply(@ws.env)
      Autoproj.message "  relspec: #{release} for #{system}: #{selection.active.size} binary packages, " \
                       "#{selection.inactive.size} built from source"
    end

    private

    def refuse(message)
      RelspecPackageSet.refuse(message)
    end

    # data/releases.yml as {release => parent or nil}: every name becomes
    # part of a file name, so each is checked (Osdeps::Reader).
    def releases
      @releases ||= begin
        path = File.join(@data, "releases.yml")
        checked(path, Relspec::Osdeps::Reader.releases(RelspecPackageSet.read_yaml(path, {})))
      end
    end

    def checked(path, reading)
      refuse("#{path}: #{reading.reason}") unless reading.ok?
      reading.value
    end

    def chosen_release
      path = File.join(@ws.config_dir, "relspec.yml")
      names = releases.keys
      expected = "expected `release: <name>` (one of #{names.join(', ')})"
      refuse("#{path}: missing; choose a release, #{expected}") unless File.file?(path)

      data = RelspecPackageSet.read_yaml(path, nil)
      refuse("#{path}: is #{shape(data)}, #{expected}") unless data.is_a?(Hash)
      unknown = data.keys - ["release"]
      refuse("#{path}: unknown key #{unknown.first.inspect}, #{expected}") unless unknown.empty?
      release = data["release"]
      refuse("#{path}: release: is #{shape(release)}, #{expected}") unless release.is_a?(String)
      return release if names.include?(release)

      refuse("#{path}: release: #{release.inspect} is not a release of this package set, #{expected}")
    end

    def shape(value)
      case value
      when nil then "empty"
      when Hash then "a mapping"
      when Array then "a list"
      else "#{value.inspect} (a #{value.class.name.downcase})"
      end
    end

    def this_system
      names, versions = @ws.os_package_resolver.operating_system
      arch, status = Open3.capture2("dpkg", "--print-architecture")
      refuse("cannot run dpkg --print-architecture: this is not a Debian system") unless status.success?
      codename = versions.find { |version| version.match?(/\A[a-z]+\z/) && version != "default" }
      System.new(Relspec::Osdeps::OperatingSystem.new(names, versions), arch.strip, codename)
    end

    # The release's ancestors first, then the release.
    def lineage(release)
      checked(File.join(@data, "releases.yml"), Relspec::Osdeps::Reader.lineage(releases, release))
    end

    # autoproj package => Debian name for this system, later releases
    # overriding earlier ones. Each name reaches autoproj's `apt-get install`
    # (as root): one that is not a Debian package name is refused (Reader).
    def mapping(lineage, system)
      mapping = {}
      lineage.each do |name|
        path = File.join(@data, "#{name}-#{system.arch}.yml")
        unless File.file?(path)
          built = Dir.glob("#{name}-*.yml", base: @data).map { |file| file.delete_prefix("#{name}-").delete_suffix(".yml") }
          # not a longer release's files (demo-child-amd64.yml is not demo's "child-amd64")
          built.reject! { |arch| releases.key?("#{name}-#{arch[/\A(.+)-[^-]+\z/, 1]}") }
          refuse(missing(lineage, name, system.arch, built.sort.join(", ")))
        end
        osdeps = RelspecPackageSet.read_yaml(path, {})
        found = checked(path, Relspec::Osdeps::Reader.resolve(osdeps, system.os))
        if found.empty?
          refuse(missing(lineage, name, system, labels(osdeps).join("; ")))
        end
        mapping.merge!(found)
      end
      mapping
    end

    # The release the user chose (the lineage's last) is what does not
    # exist; when an ancestor is what lacks the system, it is named too.
    def missing(lineage, name, system, built)
      chosen = lineage.last
      return "the release #{name} does not exist for #{system} (it is built for #{built})" if name == chosen

      "the release #{chosen} does not exist for #{system}: its ancestor #{name} is not built for it " \
        "(#{name} is built for #{built})"
    end

    def labels(osdeps)
      osdeps.values.grep(Hash).flat_map do |entry|
        entry.flat_map { |type, by_labels| by_labels.is_a?(Hash) ? by_labels.keys.map { |labels| "#{type} #{labels}" } : [] }
      end.uniq.sort
    end

    def indices(lineage, system)
      lineage.map do |name|
        path = File.join(@data, "packages", name, system.codename, "#{system.arch}.yml")
        data = File.file?(path) ? RelspecPackageSet.read_yaml(path, {}) : {}
        refuse("#{path}: is not a mapping of packages") unless data.is_a?(Hash)
        Index.new(data.to_h do |deb, fields|
          fields = {} unless fields.is_a?(Hash)
          [deb, Entry.new(deb, fields["depends"], fields["provides"])]
        end)
      end
    end

    def blacklist
      path = File.join(@ws.config_dir, "deb_blacklist.yml")
      return [] unless File.file?(path)

      list = RelspecPackageSet.read_yaml(path, [])
      refuse("#{path}: is #{shape(list)}, expected a list of package names or patterns") unless list.is_a?(Array)

      list.each_with_index.map do |item, index|
        location = "#{path} entry #{index + 1}"
        pattern = item.is_a?(String) && Relspec::Osdeps::BlacklistReading.parse(item)
        unless pattern.is_a?(Relspec::Osdeps::BlacklistReading)
          refuse("#{location}: #{pattern ? pattern.message : "#{item.inspect} is not a name or a pattern"}")
        end
        BlacklistEntry.new(pattern, location)
      end
    end

    # `autoproj update` (or aup): the time a user asks for what is new,
    # so apt's lists of the release are refreshed even when nothing of the
    # package set changed (a republished package).
    def updating?
      %w[autoproj aup].include?(File.basename($PROGRAM_NAME)) &&
        (File.basename($PROGRAM_NAME) == "aup" || ARGV.reject { |arg| arg.start_with?("-") }.first == "update")
    end

    def record(release, selection)
      state = File.join(@dir, "state")
      FileUtils.mkdir_p(state)
      File.write(File.join(state, "release"), "#{release}\n")
      File.write(File.join(state, "inactive.yml"), YAML.dump(selection.inactive))
      # what the removal (docs/releasing.md) gives to apt-get purge
      File.write(File.join(state, "packages"), selection.active.values.uniq.sort.map { |deb| "#{deb}\n" }.join)
      selection.unmatched.each do |entry|
        Autoproj.warn "relspec: #{entry.location}: #{entry.pattern.source.inspect} matches no package of #{release}"
      end
    end
  end
end
