# frozen_string_literal: true

require "fileutils"
require "open3"
require "yaml"
require_relative "workspace_templates"

# Creates real autoproj workspaces for tests and the shipped example: local
# git repositories with fixed identities and dates (so commit ids never
# change), a local package set, autoproj/manifest, .autoproj/config.yml, and
# checkouts cloned with `-o autobuild` the way `autoproj update` leaves them.
#
#   builder = WorkspaceBuilder.new("/tmp/x")
#   builder.package "base/cmake", type: :cmake, date: "2020-06-01T10:00:00Z"
#   builder.layout "base/cmake"
#   root = builder.create
class WorkspaceBuilder
  DEFINITIONS = { cmake: "cmake_package", autotools: "autotools_package", ruby: "ruby_package",
                  import: "import_package", orogen: "orogen_package" }.freeze

  Package = Struct.new(:name, :type, :date, :version, :dependencies, :optional, :osdeps, :files, :tag,
                       :checkout, :manifest, :history, keyword_init: true)

  attr_reader :base, :root, :package_set_name, :packages

  # +base+: an empty folder; the workspace is created in base/workspace and
  # its package repositories inside the workspace (base/workspace/repositories)
  # so that no absolute path of the machine ends up in what relspec reads.
  def initialize(base, package_set: "demo.pkgs")
    @base = File.expand_path(base)
    @root = File.join(@base, "workspace")
    @package_set_name = package_set
    @packages = {}
    @metapackages = {}
    @layout = []
    @excluded = []
    @ignored = []
    @osdeps = ""
    @autobuild = ""
  end

  # +files+ are extra source files (path => content); +osdeps+ are OS
  # dependency names declared in manifest.xml next to the package ones;
  # +tag+ is what source.yml makes autoproj follow; +history+ lists earlier
  # commits ({date:, tag:}) made before the final one at +date+.
  def package(name, type:, date:, version: "1.0", dependencies: [], optional: [], osdeps: [], files: {}, tag: nil,
              checkout: true, manifest: nil, history: [])
    @packages[name] = Package.new(name: name, type: type, date: date, version: version, dependencies: dependencies,
                                  optional: optional, osdeps: osdeps, files: files, tag: tag, checkout: checkout,
                                  manifest: manifest, history: history)
  end

  def metapackage(name, *members)
    @metapackages[name] = members
  end

  def layout(*names)
    @layout.concat(names)
  end

  def exclude(*names)
    @excluded.concat(names)
  end

  def ignore(*names)
    @ignored.concat(names)
  end

  # The package set's .osdeps file, verbatim.
  def osdeps(yaml)
    @osdeps = yaml
  end

  # Ruby added to the package set's packages.autobuild, verbatim (an
  # exclusion, a weak metapackage).
  def autobuild(code)
    @autobuild += code
  end

  def create
    raise ArgumentError, "#{root} already exists" if File.exist?(root)

    template = Templates.fetch(definition) { |dir| WorkspaceBuilder.new(dir, package_set: package_set_name).build_like(self) }
    Templates.copy(template, root)
    root
  end

  # The workspace as +other+ defines it, made here with git.
  def build_like(other)
    @packages, @metapackages, @layout, @excluded, @ignored, @osdeps, @autobuild = other.definition
    write_config
    write_package_set
    @packages.each_value { |package| create_repository(package) }
    @packages.each_value { |package| check_out(package) if package.checkout }
    root
  end

  # What the workspace holds, whatever folder it is made in.
  def definition
    [@packages, @metapackages, @layout, @excluded, @ignored, @osdeps, @autobuild]
  end

  def repository(name)
    File.join(root, "repositories", "#{name}.git")
  end

  def source_dir(name)
    File.join(root, "src", name)
  end

  # The commit a package's checkout holds.
  def commit_of(name)
    git(source_dir(name), "rev-parse", "HEAD")
  end

  GIT_ENVIRONMENT = {
    "GIT_AUTHOR_NAME" => "Workspace Builder", "GIT_AUTHOR_EMAIL" => "builder@example.org",
    "GIT_COMMITTER_NAME" => "Workspace Builder", "GIT_COMMITTER_EMAIL" => "builder@example.org",
    "GIT_CONFIG_NOSYSTEM" => "1", "GIT_CONFIG_GLOBAL" => File::NULL, "GIT_TERMINAL_PROMPT" => "0"
  }.freeze

  def git(dir, *args, date: "2020-01-01T00:00:00Z")
    environment = GIT_ENVIRONMENT.merge("GIT_AUTHOR_DATE" => date, "GIT_COMMITTER_DATE" => date)
    output, status = Open3.capture2e(environment, "git", "-c", "init.defaultBranch=master", *args, chdir: dir)
    raise "git #{args.join(' ')} failed in #{dir}: #{output}" unless status.success?

    output.strip
  end

  private

  # A script (#! line) is committed executable, as in real repositories.
  def write(path, content)
    FileUtils.mkdir_p(File.dirname(path))
    File.write(path, content)
    File.chmod(0o755, path) if content.start_with?("#!")
  end

  def write_config
    write(File.join(root, ".autoproj", "config.yml"), <<~YAML)
      source: src
      osdeps_mode: all
      apt_dpkg_update: false
      interactive: false
    YAML
    manifest = { "package_sets" => ["../package_sets/#{package_set_name}"], "layout" => @layout }
    manifest["exclude_packages"] = @excluded unless @excluded.empty?
    manifest["ignore_packages"] = @ignored unless @ignored.empty?
    write(File.join(root, "autoproj", "manifest"), YAML.dump(manifest))
  end

  def write_package_set
    dir = File.join(root, "package_sets", package_set_name)
    write(File.join(dir, "source.yml"), YAML.dump(
                                          "name" => package_set_name,
                                          "version_control" => [{ ".*" => { "type" => "git", "url" => "$AUTOPROJ_ROOT/repositories/$PACKAGE.git",
                                                                            "branch" => "master" } }] +
                                            @packages.values.select(&:tag).map { |package| { package.name => { "tag" => package.tag } } }
                                        ))
    write(File.join(dir, "packages.autobuild"), autobuild_definitions)
    write(File.join(dir, "#{package_set_name}.osdeps"), @osdeps)
  end

  def autobuild_definitions
    definitions = @packages.values.map { |package| "#{DEFINITIONS.fetch(package.type)} '#{package.name}'\n" }
    metas = @metapackages.map { |name, members| "metapackage '#{name}', #{members.map { |m| "'#{m}'" }.join(', ')}\n" }
    (definitions + metas).join + @autobuild
  end

  def create_repository(package)
    dir = repository(package.name)
    FileUtils.mkdir_p(dir)
    git(dir, "init", "-q")
    files = { "manifest.xml" => package.manifest || manifest_xml(package) }.merge(package.files)
    package.history.each_with_index do |commit, index|
      # earlier commits hold the package too (a pin on them must build)
      files.each { |path, content| write(File.join(dir, path), content) }
      write(File.join(dir, "HISTORY"), "change #{index + 1}\n")
      git(dir, "add", "-A")
      git(dir, "commit", "-q", "-m", "Change #{index + 1}", date: commit.fetch(:date))
      git(dir, "tag", commit[:tag]) if commit[:tag]
    end
    files.each { |path, content| write(File.join(dir, path), content) }
    git(dir, "add", "-A")
    git(dir, "commit", "-q", "--allow-empty", "-m", "Import #{package.name}", date: package.date)
    git(dir, "tag", package.tag) if package.tag
  end

  def check_out(package)
    FileUtils.mkdir_p(File.dirname(source_dir(package.name)))
    git(root, "clone", "-q", "-o", "autobuild", repository(package.name), source_dir(package.name))
  end

  def manifest_xml(package)
    depends = (package.dependencies + package.osdeps).map { |name| %(  <depend package="#{name}"/>\n) }.join
    optional = package.optional.map { |name| %(  <depend_optional package="#{name}"/>\n) }.join
    <<~XML
      <package>
        <description brief="#{package.name}">The #{package.name} package of the test workspace</description>
        <version>#{package.version}</version>
        <license>BSD-3-Clause</license>
        <maintainer>Rock Packaging/rock-dev@example.org</maintainer>
      #{depends}#{optional}</package>
    XML
  end
end
