# frozen_string_literal: true

# relspec's package set (written by `relspec osdeps package-set`; do not
# edit, regenerate it). It makes an autoproj workspace use a relspec release's
# binaries instead of building those packages from source:
#
#   autoproj/relspec.yml         release: <name>     (which release; required)
#   autoproj/deb_blacklist.yml   [names or patterns]  (built from source, with
#                                                     everything that needs them)
#
# On each run it chooses the release's packages for this system, gives them to
# autoproj as OS packages, points apt at the release's repositories (and its
# ancestors') and adds the installed packages' env.yml to the workspace's
# environment. It writes nothing into this package set except state/.

require "yaml"
require "fileutils"
require "open3"
require_relative "lib/relspec/osdeps/operating_system"
require_relative "lib/relspec/osdeps/blacklist_reading"
require_relative "lib/relspec/osdeps/selection"

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
      selection = Relspec::Osdeps::Selection.new(mapping, indices(lineage, system), blacklist)
      record(release, selection)
      @ws.os_package_resolver.merge(
        Autoproj::OSPackageResolver.new(selection.active.transform_values { |deb| { "default" => deb } },
                                        File.join(@dir, "state", "relspec.osdeps"))
      )
      AptSources.new(@data, lineage, system.codename).install
      selection.active.each_value { |deb| Environment.load(@ws.env, deb) }
      Autoproj.message "  relspec: #{release} for #{system}: #{selection.active.size} binary packages, " \
                       "#{selection.inactive.size} built from source"
    end

    private

    def refuse(message)
      raise Autoproj::ConfigError, "relspec package set: #{message}"
    end

    def releases
      @releases ||= YAML.safe_load(File.read(File.join(@data, "releases.yml"))) || {}
    end

    def chosen_release
      path = File.join(@ws.config_dir, "relspec.yml")
      names = releases.keys - ["default"]
      refuse("choose a release: write `release: <name>` into #{path} (one of #{names.join(', ')})") unless File.file?(path)

      release = (YAML.safe_load(File.read(path)) || {})["release"]
      return release if names.include?(release)

      refuse("#{path} chooses the release #{release.inspect}, which this package set does not have " \
             "(it has #{names.join(', ')})")
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
      chain = [release]
      while (parent = (releases[chain.first] || {})["depends_on"])
        refuse("the release index has a depends_on cycle through #{parent}") if chain.include?(parent)

        chain.unshift(parent)
      end
      chain
    end

    # autoproj package => Debian name for this system, later releases
    # overriding earlier ones.
    def mapping(lineage, system)
      mapping = {}
      lineage.each do |name|
        path = File.join(@data, "#{name}-#{system.arch}.yml")
        unless File.file?(path)
          built = Dir.glob("#{name}-*.yml", base: @data).map { |file| file.delete_prefix("#{name}-").delete_suffix(".yml") }
          refuse("the release #{name} does not exist for #{system.arch} (it is built for #{built.sort.join(', ')})")
        end
        found = (YAML.safe_load(File.read(path)) || {}).filter_map do |package, entry|
          (deb = system.os.resolve(entry)) && [package, deb]
        end
        if found.empty?
          refuse("the release #{name} does not exist for #{system} (it is built for #{labels(path).join('; ')})")
        end
        mapping.merge!(found.to_h)
      end
      mapping
    end

    def labels(path)
      (YAML.safe_load(File.read(path)) || {}).values.flat_map do |entry|
        entry.flat_map { |type, by_labels| by_labels.keys.map { |labels| "#{type} #{labels}" } }
      end.uniq.sort
    end

    def indices(lineage, system)
      lineage.map do |name|
        path = File.join(@data, "packages", name, system.codename, "#{system.arch}.yml")
        data = File.file?(path) ? YAML.safe_load(File.read(path)) || {} : {}
        Index.new(data.to_h { |deb, fields| [deb, Entry.new(deb, fields["depends"], fields["provides"])] })
      end
    end

    def blacklist
      path = File.join(@ws.config_dir, "deb_blacklist.yml")
      return [] unless File.file?(path)

      list = YAML.safe_load(File.read(path)) || []
      refuse("#{path} must be a list of package names or patterns") unless list.is_a?(Array)

      list.each_with_index.map do |item, index|
        location = "#{path} entry #{index + 1}"
        pattern = item.is_a?(String) && Relspec::Osdeps::BlacklistReading.parse(item)
        unless pattern.is_a?(Relspec::Osdeps::BlacklistReading)
          refuse("#{location}: #{item.inspect} #{pattern ? pattern.message : 'is not a name or a pattern'}")
        end
        BlacklistEntry.new(pattern, location)
      end
    end

    def record(release, selection)
      state = File.join(@dir, "state")
      FileUtils.mkdir_p(state)
      File.write(File.join(state, "release"), "#{release}\n")
      File.write(File.join(state, "inactive.yml"), YAML.dump(selection.inactive))
      selection.unmatched.each do |entry|
        Autoproj.warn "relspec: #{entry.location}: #{entry.pattern.source.inspect} matches no package of #{release}"
      end
    end
  end

  # The apt sources of the release and its ancestors, in one file of the
  # system's apt configuration: signed-by the key shipped in data/keys (copied
  # where apt's unprivileged downloader can read it), trusted=yes only for a
  # repository its spec says is trusted. Rewritten, and apt's lists of these
  # sources updated, only when the lines change.
  class AptSources
    LIST = "/etc/apt/sources.list.d/relspec.list"
    KEYRINGS = "/etc/apt/keyrings"

    def initialize(data, lineage, codename)
      @data = data
      @lineage = lineage
      @codename = codename
      @apt = YAML.safe_load(File.read(File.join(data, "apt.yml")))
    end

    def install
      keys = {}
      lines = @lineage.map do |name|
        entry = @apt.fetch(name)
        option = if entry["key"]
                   keys[File.join(KEYRINGS, "relspec-#{name}.gpg")] = File.binread(File.join(@data, entry["key"]))
                   "signed-by=#{File.join(KEYRINGS, "relspec-#{name}.gpg")}"
                 else
                   "trusted=yes"
                 end
        "deb [#{option}] #{entry.fetch('url')} #{@codename} main\n"
      end
      text = "# written by relspec's autoproj package set\n#{lines.join}"
      return if File.file?(LIST) && File.read(LIST) == text && keys.all? { |path, key| File.file?(path) && File.binread(path) == key }

      keys.each { |path, key| put(path, key) }
      put(LIST, text)
      update
    end

    private

    def put(path, content)
      if Process.uid.zero?
        FileUtils.mkdir_p(File.dirname(path))
        File.binwrite(path, content)
        File.chmod(0o644, path)
      else
        run("sudo", "install", "-D", "-m", "0644", "/dev/stdin", path, stdin: content)
      end
    end

    # Only the release's sources, so any error apt reports is theirs. apt
    # exits 0 when a repository cannot be reached, or its Release does not
    # verify but it has lists from before (it keeps using those): refused
    # here as well, or autoproj would fail later with "Unable to locate".
    def update
      Autoproj.message "  relspec: apt-get update for #{LIST}"
      command = ["apt-get", "update", "-o", "Dir::Etc::sourcelist=#{LIST}", "-o", "Dir::Etc::sourceparts=-",
                 "-o", "APT::Get::List-Cleanup=0"]
      command.unshift("sudo") unless Process.uid.zero?
      run(*command, refuse: /^(Err:|W: GPG error|E: )/)
    end

    def run(*command, stdin: "", refuse: nil)
      output, status = Open3.capture2e(*command, stdin_data: stdin)
      return if status.success? && !(refuse && output.match?(refuse))

      raise Autoproj::ConfigError, "relspec package set: #{command.join(' ')} failed:\n#{output}"
    end
  end

  # An installed package's env.yml ({VAR => {type:, values:, priority:}},
  # symbol keys) given to the workspace's environment; negative priorities
  # last. relspec writes add_path only; add and set are the package sets'
  # other types. A package not installed yet has none: the next autoproj run reads it.
  module Environment
    module_function

    def load(env, deb)
      Dir.glob(File.join("/opt/rock/*", deb, "env.yml")).sort.each do |path|
        data = YAML.safe_load(File.read(path), permitted_classes: [Symbol]) || {}
        first, last = data.partition { |_, entry| entry[:priority].to_i >= 0 }
        (first + last).each do |name, entry|
          Array(entry[:values]).each { |value| apply(env, entry[:type], name, value) }
        end
      end
    end

    def apply(env, type, name, value)
      case type
      when :add_path then env.add_path(name, value)
      when :add then env.add(name, value)
      when :set then env.set(name, value)
      end
    end
  end
end

RelspecPackageSet::Activation.new(Autoproj.workspace, __dir__).run
