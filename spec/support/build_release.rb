# frozen_string_literal: true

require "fileutils"
require "open3"
require "rbconfig"
require_relative "workspace_builder"

# A release of small real packages for `relspec build`: an autoproj
# workspace (WorkspaceBuilder), a spec targeting bookworm/amd64 and the
# source packages `relspec compile` makes of it, in +dir+.
#
#   release = BuildRelease.new(dir, "demo")
#   release.package "base/a"                                   # an import package (copies its tree)
#   release.package "base/b", dependencies: ["base/a"]
#   release.package "base/slow", cmake: "execute_process(COMMAND sleep 5)"
#   release.compile
class BuildRelease
  EXE = File.expand_path("../../exe/relspec", __dir__)

  attr_reader :dir, :name

  def initialize(dir, name)
    @dir = dir
    @name = name
    @builder = WorkspaceBuilder.new(File.join(dir, "ws"))
    @names = []
  end

  # +cmake+: CMake code of a cmake package (configured, built and installed
  # by dh); without it, an import package.
  # +osdeps+: OS dependencies (names of #osdeps); +files+: more source
  # files (path => content).
  def package(name, dependencies: [], cmake: nil, osdeps: [], files: {})
    files = { "#{name.tr('/', '-')}.txt" => "#{name}\n" }.merge(files)
    if cmake
      files["CMakeLists.txt"] = "cmake_minimum_required(VERSION 3.10)\nproject(p NONE)\n#{cmake}\n" \
                                "install(FILES #{name.tr('/', '-')}.txt DESTINATION share)\n"
    end
    @builder.package(name, type: cmake ? :cmake : :import, date: "2020-03-01T00:00:00Z", dependencies: dependencies,
                           files: files, osdeps: osdeps)
    @names << name
  end

  # The package set's .osdeps file.
  def osdeps(yaml)
    @builder.osdeps(yaml)
  end

  def spec_path
    File.join(dir, "specs", "#{name}.yml")
  end

  # +spec+: more of the spec (YAML lines), e.g. its repository; +targets+:
  # the spec's targets (YAML flow mapping).
  def compile(spec: "", targets: "{ bookworm: [amd64] }")
    @builder.layout(*@names)
    @builder.create
    FileUtils.mkdir_p(File.dirname(spec_path))
    File.write(spec_path, "release: #{name}\nworkspace: ../ws/workspace\ntargets: #{targets}\n" \
                          "maintainer: Demo <demo@example.org>\n#{spec}")
    output, status = Open3.capture2e(RbConfig.ruby, EXE, "compile", "specs/#{name}.yml", "--out", "out", chdir: dir)
    raise "relspec compile failed: #{output}" unless status.success?

    self
  end

  def target_dir(target = "bookworm-amd64")
    File.join(dir, "out", name, target)
  end

  # A new version of +package+: +content+ at +path+ of its source, through
  # an overlay file.
  def change(package, path, content)
    overlay = File.join(dir, "overlays", package, "files", path)
    FileUtils.mkdir_p(File.dirname(overlay))
    File.write(overlay, content)
  end

  # Debian name => version of the binary packages the reprepro repository
  # repos/<name> holds for +codename+ (reprepro's own listing).
  def published(codename = "bookworm")
    output, status = Open3.capture2e("reprepro", "-b", File.join(dir, "repos", name), "list", codename)
    raise output unless status.success?

    output.lines.to_h { |line| line.split(": ", 2).last.split }
  end

  # The Debian source name of a package.
  def source(package)
    "rock-#{name}-#{package.tr('/', '-')}"
  end
end
