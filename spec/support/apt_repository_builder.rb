# frozen_string_literal: true

require "fileutils"
require "open3"

# Creates real apt repositories with reprepro, holding real .deb files built
# with dpkg-deb: what Rock release repositories are.
#
#   repo = AptRepositoryBuilder.new(dir, codenames: %w[bionic buster], architectures: %w[amd64 arm64])
#   repo.add("rock-demo-base-base-types", "2.0.20200601.103000-1~bionic", codename: "bionic", arch: "amd64",
#            depends: "rock-demo-base-base-cmake (>= 1.0)")
class AptRepositoryBuilder
  attr_reader :dir

  # +valid_for+: reprepro's ValidFor (e.g. "1d"), which writes Valid-Until.
  def initialize(dir, codenames:, architectures:, sign_with: nil, gnupg_home: nil, valid_for: nil)
    @dir = dir
    @debs = File.join(dir, ".debs")
    @gnupg_home = gnupg_home
    FileUtils.mkdir_p([File.join(dir, "conf"), @debs])
    File.write(File.join(dir, "conf", "distributions"), codenames.map do |codename|
      sign = sign_with ? "SignWith: #{sign_with}\n" : ""
      sign += "ValidFor: #{valid_for}\n" if valid_for
      "Codename: #{codename}\nSuite: #{codename}\nArchitectures: #{architectures.join(' ')} source\n" \
        "Components: main\n#{sign}"
    end.join("\n"))
    File.write(File.join(dir, "conf", "options"), "verbose\n")
    reprepro("export")
  end

  # Builds a .deb and includes it; +arch+ "all" goes to every architecture.
  def add(name, version, codename:, arch:, depends: nil, provides: nil, source: nil)
    include_deb(codename, build_deb(name, version, arch, depends: depends, provides: provides, source: source))
  end

  def add_many(packages, codename:)
    debs = packages.map do |package|
      build_deb(package.fetch(:name), package.fetch(:version), package.fetch(:arch),
                depends: package[:depends], provides: package[:provides], source: package[:source])
    end
    debs.each_slice(200) { |slice| include_deb(codename, *slice) }
  end

  def reprepro(*args)
    environment = @gnupg_home ? { "GNUPGHOME" => @gnupg_home } : {}
    output, status = Open3.capture2e(environment, "reprepro", "-b", dir, *args)
    raise "reprepro #{args.join(' ')} failed: #{output}" unless status.success?

    output
  end

  private

  def include_deb(codename, *debs)
    reprepro("includedeb", codename, *debs)
  end

  def build_deb(name, version, arch, depends:, provides:, source:)
    root = File.join(@debs, "#{name}_#{version}_#{arch}")
    FileUtils.mkdir_p(File.join(root, "DEBIAN"))
    FileUtils.mkdir_p(File.join(root, "usr", "share", "doc", name))
    File.write(File.join(root, "usr", "share", "doc", name, "README"), "#{name} #{version}\n")
    control = "Package: #{name}\nVersion: #{version}\nArchitecture: #{arch}\n"
    control << "Maintainer: Test <test@example.org>\nSection: misc\nPriority: optional\n"
    control << "Source: #{source}\n" if source
    control << "Depends: #{depends}\n" if depends
    control << "Provides: #{provides}\n" if provides
    control << "Description: test package #{name}\n"
    File.write(File.join(root, "DEBIAN", "control"), control)
    deb = "#{root}.deb"
    output, status = Open3.capture2e("dpkg-deb", "--root-owner-group", "-Zgzip", "-b", root, deb)
    raise "dpkg-deb failed: #{output}" unless status.success?

    deb
  end
end
