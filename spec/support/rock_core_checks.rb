# frozen_string_literal: true

require "fileutils"
require "open3"
require "tmpdir"
require "yaml"
require_relative "installed_system"

# The proofs bin/rock-core-release runs on the published Rock core release
# (issue: proven installable, then used), outside CI:
#
# - installable: dose-debcheck (Debian's dose-distcheck) over the release's
#   Packages against the distribution's (this machine's bookworm lists),
#   with the broken packages and why;
# - installed: every binary package of the release at once, with apt, into
#   a clean bookworm system (the sbuild tarball unpacked, as spec/toolchain
#   does), from the published repository as a user's apt source;
# - used, through the release's env.sh only: every Ruby library on its
#   RUBYLIB loads, every pkg-config file resolves and a one-line program
#   links and runs (spec/fixtures/rock_core_use), the toolchain acceptance's
#   user component (spec/fixtures/orogen_component) and one whose ports carry
#   /base/samples/RigidBodyState from base/orogen/types' typekit
#   (spec/fixtures/orogen_rbs_component) are generated, built and run.
#
# Each check gives a Result; #run writes them all to DIR/checks.yml.
class RockCoreChecks
  FIXTURES = File.expand_path("../fixtures", __dir__)
  # what a user adds to build a component: not dependencies of the release
  USER_TOOLS = %w[build-essential cmake pkg-config].freeze

  Result = Struct.new(:name, :passed, :summary, :problems, keyword_init: true)

  # Debian's archive, read for the distribution's indices of a codename
  # that is not this machine's (whose apt lists are read instead)
  DEBIAN = "http://deb.debian.org/debian"

  def initialize(dir, tarball:, codename: "bookworm", arch: "amd64", lists: "/var/lib/apt/lists")
    @dir = dir
    @repository = File.join(dir, "repository")
    @tarball = tarball
    @codename = codename
    @arch = arch
    @lists = lists
  end

  # All checks in order; a failed installation stops the use checks.
  def run
    results = [debcheck]
    installed = install
    results << installed
    results.concat(use) if installed.passed
    File.write(File.join(@dir, "checks-#{@codename}-#{@arch}.yml"), YAML.dump(results.map { |result| result.to_h.transform_keys(&:to_s) }))
    results
  end

  def packages_index
    path = File.join(@repository, "dists", @codename, "main", "binary-#{@arch}", "Packages")
    File.file?(path) ? path : raise("no #{path} (was the release published for #{@codename}/#{@arch}?)")
  end

  # The release's binary packages (no -dbgsym), from its Packages index.
  def package_names
    File.read(packages_index).scan(/^Package: (\S+)$/).flatten.grep_v(/-dbgsym\z/).uniq.sort
  end

  def debcheck
    Dir.mktmpdir("rock-core-debcheck") do |tmp|
      background = distribution_indices(tmp)
      output, error, = Open3.capture3("dose-debcheck", "--deb-native-arch=#{@arch}", "--failures", "--explain",
                                      "--fg", packages_index, *background.flat_map { |file| ["--bg", file] })
      report = YAML.safe_load(output)
      raise "dose-debcheck failed: #{error.strip}" unless report.is_a?(Hash) && report["broken-packages"]

      broken = Array(report["report"]).map { |entry| "#{entry['package']} #{entry['version']}: #{reasons(entry)}" }
      Result.new(name: "dose-debcheck", passed: report["broken-packages"].zero?,
                 summary: "#{package_names.size} release packages against #{background.size} distribution " \
                          "indices: #{report['broken-packages']} broken", problems: broken)
    end
  end

  def install
    @system = InstalledSystem.new(@tarball, system_dir)
    FileUtils.cp_r(@repository, @system.path("srv/release"))
    File.write(@system.path("etc/apt/sources.list.d/release.list"),
               "deb [trusted=yes] file:/srv/release #{@codename} main\n")
    names = package_names
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    @system.install([], packages: names + USER_TOOLS)
    Result.new(name: "install", passed: true, problems: [],
               summary: format("%<count>d release packages installed at once with apt (%<seconds>.0f s)",
                               count: names.size, seconds: Process.clock_gettime(Process::CLOCK_MONOTONIC) - started))
  rescue InstalledSystem::Failed => e
    Result.new(name: "install", passed: false, summary: "apt could not install the release",
               problems: e.message.lines.last(30).map(&:chomp))
  end

  def use
    root = Dir.glob(@system.path("opt/rock/*")).first or raise "the release installed nothing below /opt/rock"
    root = "/#{root.delete_prefix(@system.root).delete_prefix('/')}"
    %w[rock_core_use orogen_component orogen_rbs_component].each do |fixture|
      FileUtils.cp_r(File.join(FIXTURES, fixture), @system.path("tmp/#{fixture}"))
    end
    [*library_checks(root), component("orogen component (/base/Time)", "orogen_component", root,
                                      "/tmp/orogen_component /#{prefix_of(root)}", /^out: 42 us$/),
     component("orogen component (/base/samples/RigidBodyState)", "orogen_rbs_component", root,
               "/tmp/orogen_rbs_component", /^rbs out: 2 4 6 at 21 us$/)]
  end

  private

  def system_dir
    File.join(@dir, "system-#{@codename}-#{@arch}")
  end

  # The distribution's Packages, uncompressed: as this machine's apt has
  # them for its own codename, else main's from Debian's archive.
  def distribution_indices(tmp)
    lists = Dir.glob(File.join(@lists, "*_dists_#{@codename}*_binary-#{@arch}_Packages*")).sort
    return [debian_index(tmp)] if lists.empty?

    lists.map.with_index do |list, index|
      plain = File.join(tmp, "distribution-#{index}")
      text, status = Open3.capture2("/usr/lib/apt/apt-helper", "cat-file", list)
      raise "cannot read #{list}" unless status.success?

      File.write(plain, text)
      plain
    end
  end

  def debian_index(tmp)
    plain = File.join(tmp, "distribution-#{@codename}")
    url = "#{DEBIAN}/dists/#{@codename}/main/binary-#{@arch}/Packages.xz"
    _, error, status = Open3.capture3("sh", "-c", 'curl -fsS "$1" | xz -d > "$2"', "sh", url, plain)
    raise "cannot read #{url}: #{error.strip}" unless status.success?

    plain
  end

  def reasons(entry)
    Array(entry["reasons"]).map do |reason|
      missing = reason["missing"]
      missing ? "missing #{missing.dig('pkg', 'unsat-dependency')}" : "conflict #{reason.keys.join(', ')}"
    end.join("; ")
  end

  def library_checks(root)
    output, status = @system.run("bash /tmp/rock_core_use/use_checks.sh #{root}")
    lines = output.lines.map(&:chomp).grep(/\A(ruby|pc) (ok|failed) /)
    { "ruby" => "Ruby libraries load (require)", "pc" => "pkg-config files resolve and link" }.map do |kind, what|
      mine = lines.grep(/\A#{kind} /)
      failed = mine.grep(/\A#{kind} failed /).map { |line| line.delete_prefix("#{kind} failed ") }
      Result.new(name: what, passed: status.success? && !mine.empty? && failed.empty?,
                 summary: "#{mine.size - failed.size} of #{mine.size}", problems: failed)
    end
  end

  # The prefix every package's folder starts with (/opt/rock/<release>/rock-<release>).
  def prefix_of(root)
    File.join(root, File.basename(Dir.glob(@system.path("#{root}/*-base-types")).first.to_s).delete_suffix("-base-types"))
        .delete_prefix("/")
  end

  def component(name, fixture, root, args, expected)
    output, status = @system.run("for env in #{root}/*/env.sh; do . \"$env\"; done; " \
                                 "bash /tmp/#{fixture}/user_session.sh #{args}")
    passed = status.success? && output.match?(expected)
    Result.new(name: name, passed: passed, summary: output[expected].to_s,
               problems: passed ? [] : output.lines.last(25).map(&:chomp))
  end
end
