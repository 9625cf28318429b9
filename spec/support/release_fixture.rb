# frozen_string_literal: true

require "relspec/catalog/snapshot_source"
require "relspec/catalog/autoproj_source"
require "relspec/debian/naming"
require "relspec/debian/package_version"

# A release hierarchy for plan tests: the demo workspace as a catalog
# snapshot, specs written into specs/, and ancestor repositories built with
# reprepro holding stand-in packages named and versioned as relspec would.
class ReleaseFixture
  # The packages the demo workspace's layout selects (with dependencies).
  LAYOUT = %w[base/cmake base/logging base/types data/models drivers/iodrivers_base tools/legacy tools/orocos.rb].freeze

  attr_reader :root, :catalog, :builder

  def initialize(root)
    @root = root
    @builder = builder = DemoWorkspace.build(File.join(root, "ws"))
    @catalog = ReleaseFixture.demo_catalog(builder.root)
    File.write(File.join(root, "catalog.yml"), Relspec::Catalog::SnapshotSource.dump(@catalog))
    FileUtils.mkdir_p(File.join(root, "specs"))
  end

  # The demo workspace's catalog, read with autoproj once per test
  # process: every fixture's workspace is a copy of one template
  # (WorkspaceBuilder::Templates) and reads the same. Its packages are
  # frozen.
  def self.demo_catalog(root)
    @demo_catalog ||= Relspec::Catalog::AutoprojSource.load(root, Relspec::ReleaseSpec::Distributions::BUILTIN.slice("bionic", "buster", "focal"))
  end

  # +workspace+: :snapshot (catalog.yml) or :checkouts (the workspace itself)
  def spec(name, yaml, workspace: :snapshot)
    path = workspace == :snapshot ? "../catalog.yml" : "../ws/workspace"
    File.write(File.join(root, "specs", "#{name}.yml"), "release: #{name}\nworkspace: #{path}\n#{yaml}")
    "specs/#{name}.yml"
  end

  # A release without ancestors built from the workspace's checkouts:
  # what most compile tests need. Returns the spec's path below root.
  def standalone(name, select:, targets:)
    spec(name, "select: [#{select.join(', ')}]\ntargets: { #{targets} }\nmaintainer: Demo <demo@example.org>\n",
         workspace: :checkouts)
  end

  # The version relspec gives +package+ on +codename+ (revision 1), or the
  # one an ancestor built from an older commit (+commit_time+).
  def version(package, codename, commit_time: nil)
    entry = @catalog.package(package)
    upstream = Relspec::Debian::PackageVersion.upstream(entry.version, commit_time || entry.commit_time)
    Relspec::Debian::PackageVersion.new(upstream, 1, codename).to_s
  end

  def deb(release, package)
    Relspec::Debian::Naming.deb_name(prefix: "rock", release: release, package_name: package,
                                     build_type: @catalog.package(package).build_type)
  end

  # A reprepro repository in repos/<release> holding +packages+ (name =>
  # options) for every target given.
  def repository(release, targets, packages)
    path = File.join(root, "repos", release)
    codenames = targets.map(&:first).uniq
    builder = AptRepositoryBuilder.new(path, codenames: codenames, architectures: targets.map(&:last).uniq)
    targets.group_by(&:first).each do |codename, pairs|
      debs = pairs.flat_map do |_, arch|
        packages.map do |package, options|
          { name: deb(release, package), arch: arch,
            version: options[:version] || version(package, codename, commit_time: options[:commit_time]) }
        end
      end
      builder.add_many(debs, codename: codename)
    end
    path
  end
end
