# frozen_string_literal: true

require "yaml"
require "fileutils"
require "open3"
require_relative "../trust"
require_relative "refusal"

module RelspecPackageSet
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
end
