# frozen_string_literal: true

require "fileutils"
require "open3"
require "rbconfig"
require "yaml"
require_relative "real_rock_workspace"

# The offline workspace of the real buildconf (rock-core/buildconf): its
# package sets rock.core (importing orocos.toolchain) and rock, its layout
# `rock.core`, every package of ../shared/fixtures/rock-repos checked out
# where autoproj puts it. Unlike RealRockWorkspace (the toolchain's 18
# packages, listed by hand), the packages are found the way autoproj finds
# them: the package sets are loaded (`relspec catalog export`), and each
# package whose repository ../shared bundles (named after the upstream
# repository, owner dropped) is mirrored into repositories/ and cloned into
# its source folder, and autoproj/overrides.yml points the package there
# (as RealRockWorkspace does: a package pinned by tag, class_loader, is
# resolved in its repository, which must be reachable offline).
# The tutorials package set of the buildconf's manifest is not in ../shared,
# and the layout does not use it: it is left out, as a maintainer without
# network would.
class RockCoreWorkspace < RealRockWorkspace
  EXE = File.expand_path("../../exe/relspec", __dir__)
  PACKAGE_SETS = {
    "rock-core/package_set" => "rock-core-package_set", "rock-core/rock-package_set" => "rock-package_set",
    "orocos-toolchain/autoproj" => "orocos-toolchain-package_set"
  }.freeze
  # Bundles not named after the upstream repository's name.
  BUNDLE_NAMES = { "SISL" => "external-sisl", "tools-utilrb" => "utilrb" }.freeze

  def self.available?
    PACKAGE_SETS.values.all? { |bundle| File.file?(File.join(BUNDLES, "#{bundle}.bundle")) }
  end

  # Makes the workspace unless it is there (overrides.yml is written last);
  # returns the autoproj names of the packages checked out.
  def create
    overrides = File.join(root, "autoproj", "overrides.yml")
    return YAML.safe_load_file(overrides).fetch("overrides").flat_map(&:keys) if File.file?(overrides)

    write_configuration(PACKAGE_SETS.keys.first(2))
    PACKAGE_SETS.each do |github, bundle|
      dir = remote_dir(github)
      git("clone", "-q", File.join(BUNDLES, "#{bundle}.bundle"), dir) unless File.directory?(dir)
    end
    names = catalog.filter_map do |name, package|
      bundle = bundle_of(package.dig("vcs", "url").to_s)
      next unless bundle

      FileUtils.rm_rf([repository(name), File.join(root, package.fetch("source_dir"))])
      git("clone", "-q", "--mirror", bundle, repository(name))
      git("clone", "-q", "-o", "autobuild", repository(name), package.fetch("source_dir"))
      # as autoproj checks out a package pinned by tag (class_loader 0.3.8,
      # msgpack-c cpp-3.1.1; their bundles' HEAD names no branch of theirs)
      tag = package.dig("vcs", "tag")
      git("-C", package.fetch("source_dir"), "checkout", "-q", tag) if tag
      name
    end.sort
    write("autoproj/overrides.yml", "overrides:\n#{names.map { |name| override(name) }.join}")
    names
  end

  private

  # Every package the package sets define: name => snapshot entry.
  def catalog
    output, errors, status = Open3.capture3(RbConfig.ruby, EXE, "catalog", "export", root)
    raise "relspec catalog export failed: #{errors}" unless status.success?

    YAML.safe_load(output).fetch("packages")
  end

  # The bundle of an upstream git URL, nil when ../shared has none.
  def bundle_of(url)
    name = File.basename(url, ".git")
    path = File.join(BUNDLES, "#{BUNDLE_NAMES.fetch(name, name)}.bundle")
    !name.empty? && File.file?(path) ? path : nil
  end
end

# The release spec a maintainer writes for the Rock core, one spec for every
# target (bookworm/amd64 and trixie/amd64 by default): the whole layout
# (`rock.core`), the gems at the versions the toolchain needs (facets 4
# dropped what utilrb requires; rice 3 is what base/types' Ruby bindings
# build with; grape 3.1.1 declares Ruby >= 3.1 but its dsl/routing.rb
# forwards an anonymous block beside **options, which bookworm's Ruby 3.1.2
# cannot parse, and 3.0.1 parses), the project's overlays, and leave_out with a reason, for the
# targets it concerns, for what a distribution cannot have. The rest of the
# gems the package sets ask for come from RubyGems (gem_source's default).
# bookworm's archive is this machine's own (its apt lists); any other
# codename's is Debian's, verified with the debian-archive-keyring.
class RockCoreRelease
  ROOT = File.expand_path("../..", __dir__)
  GEMS = { "facets" => "3.1.0", "rice" => "3.0.0", "rake-compiler" => "0.8.3", "grape" => "3.0.1" }.freeze
  TARGETS = %w[bookworm/amd64 trixie/amd64].freeze
  HOST_CODENAME = "bookworm"
  DEBIAN = "http://deb.debian.org/debian"
  DEBIAN_KEYRING = "/usr/share/keyrings/debian-archive-keyring.gpg"
  # Debian dropped Qt4 in bullseye: no later codename has it
  QT4 = "needs Qt4 (libqt4-dev, libqt4-opengl-dev, qt4-qmake), which Debian dropped in bullseye"
  QTRUBY = "needs qtruby (Ruby bindings of Qt4), which Debian dropped in bullseye"
  # match => [reason, codenames it applies to (nil: every target)]
  LEFT_OUT = {
    "gui/vizkit" => [QTRUBY, nil], "gui/qtpropertybrowser" => [QT4, nil],
    "gui/rock_widget_collection" => [QT4, nil], "gui/vizkit3d" => [QT4, nil]
  }.freeze

  attr_reader :dir, :targets

  def initialize(dir, targets: TARGETS)
    @dir = File.expand_path(dir)
    @targets = targets.map { |target| target.split("/", 2) }.freeze
  end

  def spec_path
    File.join(dir, "specs", "rock-core.yml")
  end

  def codenames
    targets.map(&:first).uniq
  end

  # out/rock-core/<codename>-<arch>: where relspec build writes a target's results
  def target_dirs
    targets.map { |codename, arch| "#{codename}-#{arch}" }
  end

  def workspace
    @workspace ||= RockCoreWorkspace.new(dir)
  end

  # Writes what `relspec compile` needs; the workspace only once.
  def write
    workspace.create
    FileUtils.rm_rf(File.join(dir, "overlays"))
    FileUtils.cp_r(File.join(ROOT, "overlays"), dir)
    FileUtils.mkdir_p(File.dirname(spec_path))
    File.write(spec_path, spec_text)
  end

  def spec_text
    <<~YAML
      release: rock-core
      maintainer: Rock core release <rock-core@relspec.invalid>
      workspace: ../workspace
      select: [rock.core]
      targets: { #{targets_text} }
      distributions:
      #{distributions_text}
      repository: { path: ../repository, trusted: true }
      gems: { #{GEMS.map { |name, version| "#{name}: #{version}" }.join(', ')} }
      leave_out:
      #{left_out_text}
    YAML
  end

  private

  def targets_text
    codenames.map { |codename| "#{codename}: [#{targets.select { |c, _| c == codename }.map(&:last).join(', ')}]" }
             .join(", ")
  end

  def distributions_text
    codenames.map do |codename|
      archive = codename == HOST_CODENAME ? "{ host: true }" : "{ url: \"#{DEBIAN}\", keyring: #{DEBIAN_KEYRING} }"
      "  #{codename}: { archive: #{archive} }"
    end.join("\n")
  end

  def left_out_text
    LEFT_OUT.filter_map do |match, (reason, only)|
      concerned = only ? codenames & only : codenames
      next if concerned.empty?

      "  - { match: #{match}, reason: \"#{reason}\", targets: [#{concerned.join(', ')}] }"
    end.join("\n")
  end
end
