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
require_relative "lib/relspec/osdeps/trust"

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

    # data/releases.yml: {release => {depends_on: parent} or nil}; every
    # name becomes part of a file name, so each is checked.
    def releases
      @releases ||= begin
        path = File.join(@data, "releases.yml")
        index = RelspecPackageSet.read_yaml(path, {})
        refuse("#{path}: is not a mapping of releases") unless index.is_a?(Hash)
        index.each do |name, entry|
          next if name == "default"

          problem = Relspec::Osdeps::Trust.release_name(name) ||
                    (entry.is_a?(Hash) && entry["depends_on"] && Relspec::Osdeps::Trust.release_name(entry["depends_on"]))
          refuse("#{path}: #{name.inspect}: #{problem}") if problem
        end
        index
      end
    end

    def chosen_release
      path = File.join(@ws.config_dir, "relspec.yml")
      names = releases.keys - ["default"]
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
      chain = [release]
      while (parent = (releases[chain.first] || {})["depends_on"])
        refuse("the release index has a depends_on cycle through #{parent}") if chain.include?(parent)
        refuse("#{File.join(@data, 'releases.yml')}: #{chain.first} depends on #{parent}, which it does not hold") unless releases.key?(parent)

        chain.unshift(parent)
      end
      chain
    end

    # autoproj package => Debian name for this system, later releases
    # overriding earlier ones. Each name reaches autoproj's `apt-get install`
    # (as root): one that is not a Debian package name is refused.
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
        refuse("#{path}: is not a mapping of packages") unless osdeps.is_a?(Hash)
        found = osdeps.filter_map do |package, entry|
          next unless (deb = system.os.resolve(entry))

          problem = Relspec::Osdeps::Trust.debian_name(deb)
          refuse("#{path}: #{package}: #{problem}") if problem
          [package, deb]
        end
        if found.empty?
          refuse(missing(lineage, name, system, labels(osdeps).join("; ")))
        end
        mapping.merge!(found.to_h)
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

  def self.refuse(message)
    raise Autoproj::ConfigError, "relspec package set: #{message}"
  end

  # A YAML file of the package set or the workspace: plain data only; a
  # file that is not YAML is refused with its name.
  def self.read_yaml(path, empty)
    data = YAML.safe_load(File.read(path))
    data.nil? ? empty : data
  rescue Psych::Exception => e
    refuse("#{path}: is not plain YAML (#{e.message.sub(/\A\(.*?\): /, '')})")
  end

  # The apt sources of the release and its ancestors, one file per release
  # (relspec-<release>.list: workspaces on different releases each have
  # theirs, the same release is shared): signed-by the key shipped in
  # data/keys (copied where apt's unprivileged downloader can read it),
  # trusted=yes only for a repository its spec says is trusted. Every
  # entry of data/apt.yml is checked (Trust) when this is made, before
  # anything is written.
  #
  # apt's lists of these sources are updated (apt-get update, bounded)
  # when a source or key is new or changed, when apt has no lists of it,
  # when its entry in data/apt.yml changed, on `autoproj update` (a
  # republished package arrives with it), and after any failed update: state/apt/<release> records the last successful one and
  # is removed before each try.
  class AptSources
    SOURCES = "/etc/apt/sources.list.d"
    KEYRINGS = "/etc/apt/keyrings"
    LISTS = "/var/lib/apt/lists"
    # Relspec::Builder::Chroot::PACKAGE_SET_SOURCE: chroots never take these sources.
    HEADER = "# written by relspec's autoproj package set\n"
    # apt-get update: at most this long, each connection this long
    DEADLINE = 300
    CONNECTION_TIMEOUT = 30

    def initialize(data, lineage, codename, state)
      @data = data
      @codename = codename
      @state = File.join(state, "apt")
      path = File.join(data, "apt.yml")
      apt = RelspecPackageSet.read_yaml(path, {})
      RelspecPackageSet.refuse("#{path}: is not a mapping of releases") unless apt.is_a?(Hash)
      @releases = lineage.map { |name| source(path, name, apt[name]) }
    end

    # {name:, list:, text:, keyring:, key:, stamp:} of one release, checked.
    def source(path, name, entry)
      problem = entry.nil? ? "has no entry" : Relspec::Osdeps::Trust.apt_entry(entry)
      RelspecPackageSet.refuse("#{path}: #{name}: #{problem}") if problem

      release = { name: name, url: entry["url"], list: File.join(SOURCES, "relspec-#{name}.list"),
                  stamp: "#{YAML.dump(entry)}#{@codename}\n" }
      return release.merge(text: "#{HEADER}deb [trusted=yes] #{entry['url']} #{@codename} main\n") unless entry["key"]

      keyring = File.join(KEYRINGS, "relspec-#{name}.gpg")
      key = File.join(@data, entry["key"])
      real = File.file?(key) ? File.realpath(key) : ""
      unless real.start_with?("#{File.realpath(@data)}/")
        RelspecPackageSet.refuse("#{path}: #{name}: the key #{entry['key']} is not a file of the package set")
      end
      release.merge(text: "#{HEADER}deb [signed-by=#{keyring}] #{entry['url']} #{@codename} main\n",
                    keyring: keyring, key: File.binread(real))
    end

    def install(refresh: false)
      stale = @releases.reject { |release| current?(release) }
      stale.each do |release|
        put(release[:keyring], release[:key]) if release[:keyring]
        put(release[:list], release[:text])
      end
      outdated = refresh ? @releases : @releases.reject { |release| updated?(release) }
      update(@releases.select { |release| stale.include?(release) || outdated.include?(release) })
    end

    # The active packages installed here brought to the versions apt now
    # has (`autoproj update`): autoproj's own check compares the last
    # version `apt-cache show` prints, the installed one, and never
    # upgrades a republished package. Names are Trust-checked, and follow
    # `--`, so apt reads none of them as an option.
    def upgrade(debs)
      return if debs.empty?

      status, = Open3.capture2("dpkg-query", "-W", "-f", "${db:Status-Status} ${Package}\n", "--", *debs,
                               err: File::NULL)
      installed = status.lines.filter_map { |line| line.split[1] if line.start_with?("installed ") }
      return if installed.empty?

      Autoproj.message "  relspec: apt-get install --only-upgrade for #{installed.size} packages"
      command = ["env", "DEBIAN_FRONTEND=noninteractive", "timeout", DEADLINE.to_s, "apt-get", "install", "-y", "-q",
                 "--only-upgrade", "--", *installed]
      command.unshift("sudo") unless Process.uid.zero?
      run(*command)
    end

    private

    def current?(release)
      File.file?(release[:list]) && File.read(release[:list]) == release[:text] &&
        (!release[:keyring] || (File.file?(release[:keyring]) && File.binread(release[:keyring]) == release[:key]))
    end

    # apt has lists of the source, and the last update of this workspace
    # was of this very entry and succeeded.
    def updated?(release)
      marker = File.join(@state, release[:name])
      File.file?(marker) && File.read(marker) == release[:stamp] && !lists(release).empty?
    end

    # apt's list files of the source: its URL without the scheme, / as _.
    def lists(release)
      prefix = release[:url].sub(%r{\Ahttps?://}, "").chomp("/").tr("/", "_")
      Dir.glob("#{prefix}_dists_#{@codename}_*Packages*", base: LISTS)
    end

    # Only the release's sources, so any error apt reports is theirs. apt
    # exits 0 when a repository cannot be reached, or its Release does not
    # verify but it has lists from before (it keeps using those): refused
    # here as well, or autoproj would fail later with "Unable to locate".
    def update(releases)
      FileUtils.mkdir_p(@state)
      releases.each do |release|
        marker = File.join(@state, release[:name])
        FileUtils.rm_f(marker)
        Autoproj.message "  relspec: apt-get update for #{release[:list]}"
        command = ["timeout", DEADLINE.to_s, "apt-get", "update", "-o", "Dir::Etc::sourcelist=#{release[:list]}",
                   "-o", "Dir::Etc::sourceparts=-", "-o", "APT::Get::List-Cleanup=0",
                   "-o", "Acquire::http::Timeout=#{CONNECTION_TIMEOUT}", "-o", "Acquire::https::Timeout=#{CONNECTION_TIMEOUT}"]
        command.unshift("sudo") unless Process.uid.zero?
        run(*command, refuse: /^(Err:|W: GPG error|E: )/,
                      failure: "the next autoproj run tries again; #{release[:url]} must be reachable and its Release verify")
        File.write(marker, release[:stamp])
      end
    end

    def put(path, content)
      if Process.uid.zero?
        FileUtils.mkdir_p(File.dirname(path))
        File.binwrite(path, content)
        File.chmod(0o644, path)
      else
        run("sudo", "install", "-D", "-m", "0644", "/dev/stdin", path, stdin: content)
      end
    end

    def run(*command, stdin: "", refuse: nil, failure: nil)
      output, status = Open3.capture2e(*command, stdin_data: stdin)
      return if status.success? && !(refuse && output.match?(refuse))

      why = [(status.exitstatus == 124 && command.include?("timeout") ? "no answer within #{DEADLINE} s" : nil), failure]
      why = why.compact.empty? ? "" : " (#{why.compact.join('; ')})"
      RelspecPackageSet.refuse("#{command.join(' ')} failed#{why}:\n#{output}")
    end
  end

  # The env.yml of the installed active packages ({VAR => {type:, values:,
  # priority:}}, symbol keys), for the workspace's environment; negative
  # priorities last. Only a file below Trust::PREFIX, of a release of the
  # lineage, changing the variables Trust allows, to paths below the
  # prefix: read and checked as a whole before any of it is applied. A
  # package not installed yet has none: the next autoproj run reads it.
  class Environment
    def self.read(lineage, debs)
      prefix = Relspec::Osdeps::Trust::PREFIX
      paths = lineage.product(debs).map { |release, deb| File.join(prefix, release, deb, "env.yml") }
      new(paths.select { |path| File.file?(path) }.sort.flat_map { |path| operations(path) })
    end

    def self.operations(path)
      problem = Relspec::Osdeps::Trust.environment_file(path)
      RelspecPackageSet.refuse("#{path}: #{problem}") if problem
      data = YAML.safe_load(File.read(path), permitted_classes: [Symbol]) || {}
      RelspecPackageSet.refuse("#{path}: is not a mapping of variables") unless data.is_a?(Hash)
      data.each do |name, entry|
        problem = Relspec::Osdeps::Trust.environment(name, entry)
        RelspecPackageSet.refuse("#{path}: #{problem}") if problem
      end
      first, last = data.partition { |_, entry| entry[:priority].to_i >= 0 }
      (first + last).flat_map do |name, entry|
        Array(entry[:values]).map { |value| [entry[:type], name, value] }
      end
    rescue Psych::Exception => e
      RelspecPackageSet.refuse("#{path}: is not plain YAML (#{e.message})")
    end

    def initialize(operations)
      @operations = operations
    end

    def apply(env)
      @operations.each do |type, name, value|
        case type
        when :add_path then env.add_path(name, value)
        when :add then env.add(name, value)
        when :set then env.set(name, value)
        end
      end
    end
  end
end

RelspecPackageSet::Activation.new(Autoproj.workspace, __dir__).run
