# frozen_string_literal: true

require_relative "workspace_builder"

# The demo workspace: what the tests load and what examples/ ships. A small
# Rock-like stack covering every build type relspec packages, a metapackage,
# an optional dependency, an excluded and an ignored package, and OS
# dependencies that differ between bionic and buster (the demo pretends that
# buster has no motif, so tools/legacy cannot exist there).
module DemoWorkspace
  OSDEPS = <<~YAML
    boost:
      ubuntu:
        '18.04,bionic': [libboost-system-dev, libboost-thread-dev]
        default: libboost-all-dev
      debian:
        buster: libboost1.67-all-dev
        default: libboost-dev
    eigen:
      ubuntu,debian: libeigen3-dev
    motif:
      ubuntu: libmotif-dev
      debian:
        buster: nonexistent
        default: libmotif-dev
    yaml-cpp:
      debian,ubuntu: libyaml-cpp-dev
    nokogiri: gem
    qt5-tools:
      ubuntu: ignore
      debian: qttools5-dev-tools
  YAML

  CMAKE_LISTS = <<~CMAKE
    cmake_minimum_required(VERSION 3.10)
    project(%<project>s VERSION %<version>s LANGUAGES NONE)
    install(FILES README DESTINATION share/%<project>s)
  CMAKE

  # name => [build type, commit date, manifest version, dependencies, optional, osdeps]
  PACKAGES = {
    "base/cmake" => [:cmake, "2020-05-04T08:00:00Z", "1.0", [], [], []],
    "base/types" => [:cmake, "2020-06-01T10:30:00Z", "2.0", ["base/cmake"], ["base/logging"], %w[boost eigen]],
    "base/logging" => [:cmake, "2020-05-20T12:00:00Z", "1.1", ["base/cmake"], [], []],
    "drivers/iodrivers_base" => [:cmake, "2020-06-03T09:15:00Z", "1.0", ["base/types", "base/logging"], [], ["boost"]],
    "tools/orocos.rb" => [:ruby, "2020-06-05T16:45:00Z", "0.9", ["base/types", "tools/unused"], [],
                          %w[nokogiri qt5-tools ruby]],
    "tools/legacy" => [:autotools, "2019-11-11T11:11:11Z", "0.1", [], [], %w[motif yaml-cpp]],
    "data/models" => [:import, "2020-04-01T00:00:00Z", "3", [], [], []],
    "drivers/old_driver" => [:cmake, "2018-01-01T00:00:00Z", "0.1", ["base/types"], [], []]
  }.freeze

  # base/types has an older release tagged v2.0.0 (what demo-child pins)
  HISTORY = { "base/types" => [{ date: "2020-03-02T14:00:00Z", tag: "v2.0.0" }] }.freeze

  module_function

  def build(base)
    builder = WorkspaceBuilder.new(base)
    PACKAGES.each do |name, (type, date, version, dependencies, optional, osdeps)|
      builder.package(name, type: type, date: date, version: version, dependencies: dependencies, optional: optional,
                            osdeps: osdeps, files: files_for(name, type, version), history: HISTORY.fetch(name, []))
    end
    # ignored by the manifest, and never checked out: dependencies on it vanish
    builder.package("tools/unused", type: :import, date: "2020-01-01T00:00:00Z", checkout: false)
    builder.ignore("tools/unused")
    builder.metapackage("demo.core", "base/types", "base/logging", "drivers/iodrivers_base", "tools/orocos.rb")
    builder.layout("demo.core", "data/models", "tools/legacy")
    builder.exclude("drivers/old_driver")
    builder.osdeps(OSDEPS)
    builder.create
    builder
  end

  # base/logging really needs base/cmake at build time: it looks for the
  # file base/cmake installs, the way Rock packages find Rock's CMake macros.
  NEEDS_BASE_CMAKE = <<~CMAKE
    find_path(BASE_CMAKE_DIR base-cmake/README PATH_SUFFIXES share REQUIRED)
    message(STATUS "found base/cmake in ${BASE_CMAKE_DIR}")
  CMAKE

  # An autotools package that really builds: configure writes the Makefile
  # that dh_auto_build and dh_auto_install run.
  CONFIGURE_AC = <<~AC
    AC_INIT([%<project>s], [%<version>s])
    AC_CONFIG_FILES([Makefile])
    AC_OUTPUT
  AC

  MAKEFILE_IN = <<~MAKE
    prefix = @prefix@
    all:
    install:
    	mkdir -p $(DESTDIR)$(prefix)/share/%<project>s
    	cp README $(DESTDIR)$(prefix)/share/%<project>s/
  MAKE

  def files_for(name, type, version)
    project = name.tr("/", "-")
    readme = { "README" => "#{name}: part of the relspec demo workspace.\n" }
    cmake = format(CMAKE_LISTS, project: project, version: version)
    cmake += NEEDS_BASE_CMAKE if name == "base/logging"
    case type
    when :cmake then readme.merge("CMakeLists.txt" => cmake)
    when :autotools then readme.merge("configure.ac" => format(CONFIGURE_AC, project: project, version: version),
                                      "Makefile.in" => format(MAKEFILE_IN, project: project))
    when :ruby then readme.merge("lib/#{File.basename(name, '.rb')}.rb" => "module Orocos\nend\n")
    else readme
    end
  end
end
