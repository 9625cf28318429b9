# frozen_string_literal: true

require "spec_helper"
require "open3"

# A package set giving a package another package's prefix as a CMake define
# (rock.core: `pkg.define 'SISL_PREFIX', package('external/sisl').prefix`),
# in autoproj's default layout, where every package's prefix is the same
# $AUTOPROJ_ROOT/install: debian/rules gets the prefix the release gives the
# named package, not the workspace's folder.
RSpec.describe "a define naming another package's prefix" do
  before(:all) do
    @base = Dir.mktmpdir("relspec-prefix-defines")
    builder = WorkspaceBuilder.new(@base)
    builder.package("external/dep", type: :cmake, date: "2020-06-01T10:00:00Z")
    builder.package("external/gone", type: :cmake, date: "2020-06-01T10:00:00Z")
    builder.package("app", type: :cmake, date: "2020-06-02T10:00:00Z", dependencies: %w[external/dep])
    builder.autobuild(<<~RUBY)
      setup_package 'app' do |pkg|
        pkg.define 'DEP_PREFIX', package('external/dep').prefix
        pkg.define 'DEP_CMAKE', File.join(package('external/dep').prefix, 'share', 'cmake')
        pkg.define 'GONE_PREFIX', package('external/gone').prefix
        pkg.define 'WORKSPACE_PREFIX', Autobuild.prefix
        pkg.define 'RUBY_EXECUTABLE', Autoproj.config.ruby_executable
        pkg.env_set 'ROCK_PREFIX', File.join(pkg.prefix, 'share', 'app')
      end
    RUBY
    builder.create
    FileUtils.mkdir_p(File.join(@base, "specs"))
    { "shared" => [false, "bookworm: [amd64]"], "separate" => [true, "bookworm: [amd64]"],
      "two" => [false, "bookworm: [amd64], trixie: [amd64]"] }.each do |release, (separate, targets)|
      File.write(File.join(@base, "specs", "#{release}.yml"), <<~YAML)
        release: #{release}
        maintainer: Rock Packaging <rock@example.org>
        workspace: ../workspace
        select: [app]
        targets: { #{targets} }
        separate_prefixes: #{separate}
      YAML
    end
  end

  after(:all) { FileUtils.rm_rf(@base) if @base }

  def debian_file(release, source, name, target: "*")
    tarball = Dir.glob(File.join(@base, "out", release, target, "**", "#{source}_*.debian.tar.xz")).first
    text, status = Open3.capture2("tar", "-xJOf", tarball, "debian/#{name}")
    raise "no debian/#{name} in #{tarball}" unless status.success?

    text
  end

  it "gets the release prefix of the package it names, a shared or a separate one" do
    {
      "shared" => %w[/opt/rock/shared /opt/rock/shared],
      "separate" => %w[/opt/rock/separate/rock-separate-external-dep /opt/rock/separate/rock-separate-app]
    }.each do |release, (dep_prefix, app_prefix)|
      run = relspec("compile", "specs/#{release}.yml", "--out", "out", chdir: @base)
      expect(run.exit_code).to eq(0), run.stderr
      rules = debian_file(release, "rock-#{release}-app", "rules")
      expect(rules).to include("-DDEP_CMAKE=#{dep_prefix}/share/cmake -DDEP_PREFIX=#{dep_prefix} ")
      # a package the release does not have: left out, as if autoproj had not seen it
      expect(rules).not_to include("GONE_PREFIX")
      # the workspace's own prefix is not a package's: kept as the package set wrote it
      expect(rules).to include("'-DWORKSPACE_PREFIX=$$AUTOPROJ_ROOT/install'")
      expect(rules).not_to include(".relspec-prefix-of")
      # the package's own prefix in its environment is still its release prefix
      expect(debian_file(release, "rock-#{release}-app", "env.yml")).to include("- \"#{app_prefix}/share/app\"\n")
    end
  end

  # rock.core: `pkg.define "RUBY_EXECUTABLE", Autoproj.config.ruby_executable`,
  # relspec's own Ruby when it loads the workspace (/usr/bin/ruby3.1 here)
  it "names each target's Ruby where the package set names the workspace's" do
    run = relspec("compile", "specs/two.yml", "--out", "out", chdir: @base)
    expect(run.exit_code).to eq(0), run.stderr
    rules = %w[bookworm trixie].to_h { |codename| [codename, debian_file("two", "rock-two-app", "rules", target: "#{codename}-amd64")] }
    expect(rules["bookworm"]).to include("-DRUBY_EXECUTABLE=/usr/bin/ruby3.1 ")
    expect(rules["trixie"]).to include("-DRUBY_EXECUTABLE=/usr/bin/ruby3.3 ")
    expect(rules["trixie"]).not_to include(RbConfig.ruby)
  end
end
