# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "../../support/rock_workspace_context"
require_relative "../../support/rock_gems"
require_relative "../../support/installed_system"

# Real Rock packages, as a release maintainer compiles them: base/cmake,
# base/logging, base/types and utilrb from their real repositories (git
# bundles in ../shared), described by the project's own package sets,
# compiled for bookworm/amd64 with no overlays, every package built by
# `relspec build` with sbuild in a clean chroot (in dependency order), the
# .debs installed with apt into another clean bookworm system (made from
# the same chroot tarball; apt fetches their Depends from the archive),
# then used there through the packages' env.sh only. The release is
# compiled, built and installed once for the whole group (base/types takes
# most of the time).
RSpec.describe "a release of real Rock packages" do
  let(:release) { "rock" }

  include_context "a real Rock workspace"

  before(:all) do
    @facets = RockGems.facets(File.join(@dir, "gems"))
    # offline, a stand-in with the two files utilrb loads; CI always builds the real gem
    raise "facets-3.1.0.gem is neither in #{RockGems::CACHE} nor fetchable" if @facets == :stand_in && ENV["CI"]

    need_fixture(RockGems.rice(File.join(@dir, "gems")), "rice-3.0.0.gem is neither in #{RockGems::CACHE} nor fetchable")
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "rock.yml"), <<~YAML)
      release: rock
      workspace: ../ws/workspace
      targets: { bookworm: [amd64] }
      maintainer: Rock Packaging <rock-dev@example.org>
      # this machine's apt lists stand for bookworm's archive: it has no
      # ruby-rice, so rice is packaged without a gems: entry, at the highest
      # version of ../gems that fits Rock's osdeps (rice<4.0.0)
      distributions: { bookworm: { archive: { host: true } } }
      # utilrb needs facets/kernel/constant: facets 4 dropped it, and Rock's
      # osdeps do not constrain facets, so it stays pinned
      gems: { facets: "3.1.0" }
      gem_source: ../gems
    YAML
    @compile = relspec("compile", "specs/rock.yml", "--out", "out", chdir: @dir)
    raise "compile failed: #{@compile.stderr}" unless @compile.exit_code.zero?

    @target = File.join(@dir, "out", "rock", "bookworm-amd64")
    @plan = YAML.safe_load(File.read(File.join(@target, "plan.yml")))
    @build = relspec("build", "specs/rock.yml", "--out", "out", "--backend", "sbuild", "--jobs", "2", chdir: @dir)
    @results = YAML.safe_load(File.read(File.join(@target, "build-results.yml")))
    raise "build failed:\n#{@build.stdout}#{@build.stderr}#{failed_logs}" unless @build.exit_code.zero?

    @debs = @results.fetch("packages").values.to_h do |record|
      [record.fetch("package"), record.fetch("files").map { |file| File.join(@target, file.fetch("name")) }.grep(/[.]deb\z/)]
    end
    @system = InstalledSystem.new(File.join(CliRunner::CACHE, "relspec", "chroots", "bookworm-amd64.tar.zst"),
                                  File.join(@dir, "system"))
    # pkg-config is the user's tool for the C++ check, not a dependency of the release
    @install = @system.install(@debs.values.flatten.grep_v(/-dbgsym_/), packages: %w[pkg-config])
    # a Rock user's machine has autoproj's own utilrb and facets, newer than the release's
    @system.install_gems(%w[utilrb facets].map { |name| (Gem.loaded_specs[name] || Gem::Specification.find_by_name(name)).cache_file })
  end

  # The end of the log of each package that did not build, for the failure message.
  def failed_logs
    @results.fetch("packages").values.select { |record| record["status"] == "failed" }.map do |record|
      "\n--- #{record['log']}:\n#{File.readlines(File.join(@target, record['log'])).last(60).join}"
    end.join
  end

  def debian_file(source, path)
    tarball = Dir.glob(File.join(@target, source, "*.debian.tar.xz")).first
    output, status = Open3.capture2("tar", "-xOJf", tarball, "debian/#{path}")
    raise "no debian/#{path} in #{tarball}" unless status.success?

    output
  end

  def prefix(source)
    "/opt/rock/rock/#{source}"
  end

  it "packages rice automatically at the version Rock's osdeps accept, and records it in the lock" do
    lock = YAML.safe_load(File.read(File.join(@dir, "releases", "rock", "lock.yml")))
    expect(lock.dig("packages", "rice")).to include("url" => "../gems/rice-3.0.0.gem", "version" => "3.0.0")
    expect(lock.dig("targets", "bookworm/amd64", "rice")).to include("decision" => "build")
  end

  it "compiles every package of the layout, and facets as a gem of the release" do
    expect(@plan.fetch("builds").map { |build| build["package"] })
      .to eq(%w[base/cmake facets rice base/logging utilrb base/types])
    # (one .deb per package, besides the -dbgsym ones sbuild makes of compiled code)
    expect(@debs.values.map { |debs| debs.grep_v(/-dbgsym_/).size }.uniq).to eq([1])
    expect(Dir.exist?(File.join(@workspace.root, "overlays"))).to be(false)
  end

  # In a clean chroot, a package builds only when its debian/control names
  # every build-dependency: those of the distribution come from its archive,
  # those of the release from the .debs built before it in the same run.
  it "builds every package with sbuild in a clean chroot" do
    expect(@results.fetch("backend")).to eq("sbuild")
    expect(@results.fetch("packages").values.map { |record| record["status"] }.uniq).to eq(["built"])
    log = File.read(File.join(@target, "logs", "rock-rock-base-types.log"))
    expect(log).to include("--chroot-mode=unshare")
    %w[rock-rock-base-cmake rock-rock-base-logging rock-rock-ruby-rice].each do |dependency|
      expect(log).to match(/Unpacking #{dependency} /)
    end
    # rice's headers include ruby.h: base/types' bindings find Ruby only because rice brings ruby-dev
    binary = debian_file("rock-rock-ruby-rice", "control").split("\n\n").last
    expect(binary[/^Depends:.*?(?=\n\S)/m].split(/,\s*/)).to include("ruby-dev")
    expect(log).to match(/Unpacking ruby3[.]\d+-dev[: ]/)
  end

  it "builds base/types against its whole dependency closure and with the package set's defines" do
    rules = debian_file("rock-rock-base-types", "rules")
    # debian/rules names the direct dependencies only (rice: base/types' Ruby bindings, an optional
    # dependency the release can provide); the search paths of the whole closure come from their
    # installed env.sh at build time (spec/relspec/debian/build_environment_spec.rb), which is how
    # base/types found them in the clean chroot above
    expect(rules).to include("RELSPEC_DEPENDENCIES := #{prefix('rock-rock-base-cmake')} " \
                             "#{prefix('rock-rock-base-logging')} #{prefix('rock-rock-ruby-rice')}\n")
    expect(rules).to include("export CMAKE_PREFIX_PATH := $(call relspec_get,CMAKE_PREFIX_PATH)\n")
    expect(rules).to include("export PKG_CONFIG_PATH := $(call relspec_get,PKG_CONFIG_PATH)\n")
    expect(rules).to include("-DCMAKE_BUILD_TYPE=Release -DROCK_TEST_ENABLED=OFF -DUSE_SISL=OFF " \
                             "-DCMAKE_INSTALL_PREFIX=$(PREFIX)")
  end

  # apt resolved every Depends of the release's packages from bookworm's archive (ruby, boost, …)
  it "installs every package with apt into a clean bookworm system, with its dependencies" do
    expect(@install).to match(/^Setting up rock-rock-base-types /)
    listed, status = @system.run("dpkg-query -W -f '${Package} ${Status}\\n' 'rock-rock-*'")
    expect(status).to be_success, listed
    installed = listed.lines.map(&:split).select { |fields| fields.last == "installed" }.map(&:first)
    expect(installed).to match_array(@results.fetch("packages").keys)
    audit, status = @system.run("dpkg --audit")
    expect([audit, status.success?]).to eq(["", true])
  end

  it "lets a C++ program use a base/types header and its pkg-config file through env.sh only" do
    program = <<~CPP
      #include <base/Angle.hpp>
      #include <iostream>
      int main() { std::cout << base::Angle::fromDeg(90).getDeg() << std::endl; return 0; }
    CPP
    File.write(@system.path("root/angle.cpp"), program)
    output, status = @system.run(<<~SH)
      set -eu
      cd /root
      . #{prefix('rock-rock-base-types')}/env.sh
      g++ -std=c++11 -o angle angle.cpp $(pkg-config --cflags --libs base-types)
      ./angle
    SH
    expect(status).to be_success, output
    expect(output.lines.last).to eq("90\n")
  end

  # The system has utilrb 3.2.0 and facets 4.0.0 installed as gems (autoproj's own dependencies),
  # both newer than the release's: the release's code must still be what Ruby loads.
  it "lets Ruby load utilrb and facets through env.sh only, with an empty GEM_HOME" do
    output, status = @system.run(<<~SH)
      set -eu
      . #{prefix('rock-rock-ruby-utilrb')}/env.sh
      export GEM_HOME=$(mktemp -d)
      ruby -e 'require "utilrb/logger"; require "backports/2.5.0/hash/slice"; puts Logger::Hierarchy.name
               puts $LOADED_FEATURES.grep(%r{/(utilrb/logger|facets/kernel/constant)[.]rb$}).sort'
    SH
    expect(status).to be_success, output
    # (utilrb 3.0.1 extends ::Logger; Ruby records the files by their real paths)
    lines = output.lines.map(&:chomp)
    expect(lines).to include("Logger::Hierarchy")
    # (the real facets 3.1.0 keeps its files in lib/core; the offline stand-in in lib)
    expect(lines.grep(%r{/(utilrb/logger|facets/kernel/constant)[.]rb\z}))
      .to match([%r{\A#{prefix('rock-rock-ruby-facets')}/gems/gems/facets-3.1.0/lib/(core/)?facets/kernel/constant[.]rb\z},
                 "#{prefix('rock-rock-ruby-utilrb')}/gems/gems/utilrb-3.0.1/lib/utilrb/logger.rb"])
  end

  it "names the upstream copyright holders and the license by its DEP-5 short name" do
    copyright = debian_file("rock-rock-base-cmake", "copyright")
    expect(copyright).to include("Copyright: DFKI <robotik@dfki.de>\n Sylvain Joyeux <sylvain.joyeux@m4x.org>\n")
    expect(copyright).to include("License: LGPL-2+\n base/cmake declares its license as: LGPL v2 or later\n")
    expect(copyright).not_to include("rock-dev@example.org")
    expect(debian_file("rock-rock-ruby-utilrb", "copyright")).to include("License: CeCILL-B\n")
    %w[rock-rock-base-cmake rock-rock-base-types rock-rock-ruby-utilrb].each do |source|
      expect(debian_file(source, "changelog") + debian_file(source, "copyright")).not_to include("$AUTOPROJ_ROOT")
    end
  end

  # lintian errors of upstream's own files that relspec does not rewrite (none known yet).
  UPSTREAM_LINTIAN_ERRORS = [].freeze

  it "passes lintian on every source and binary package with no errors" do
    files = Dir.glob(File.join(@target, "*", "*.dsc")).sort + @debs.values.flatten
    output, = Open3.capture2e("lintian", "--no-tag-display-limit", *files)
    errors = output.lines.grep(/\AE: /).reject { |line| UPSTREAM_LINTIAN_ERRORS.any? { |known| line.include?(known) } }
    expect(errors).to eq([]), output
    # the overrides cover /opt/rock, /opt/rock/<release> and the prefixes
    expect(output).not_to include("dir-or-file-in-opt")
  end

  it "sources shared dependencies once, keeps the system gem path, and works under set -u" do
    output, status = @system.run(<<~SH)
      set -eu
      . #{prefix('rock-rock-base-types')}/env.sh
      . #{prefix('rock-rock-base-logging')}/env.sh
      echo "$CMAKE_PREFIX_PATH"
      ruby -e 'puts Gem.path.include?(Gem.default_dir)'
    SH
    expect(status).to be_success, output
    cmake_path, gem_default = output.lines.map(&:chomp)
    # base/types' dependencies are sourced in order (base/cmake, base/logging, rice), each prepending
    # itself; base/logging's own base/cmake is not added again
    expect(cmake_path.split(":")).to eq([prefix("rock-rock-base-types"), prefix("rock-rock-ruby-rice"),
                                         prefix("rock-rock-base-logging"), prefix("rock-rock-base-cmake")])
    expect(gem_default).to eq("true")
  end
end
