# frozen_string_literal: true

require "spec_helper"
require "yaml"
require "relspec/catalog/release_catalog"
require_relative "../../support/real_rock_workspace"
require_relative "../../support/gem_builder"

# The REAL Rock package sets (rock.core, which imports orocos.toolchain), read
# as autoproj reads them: what the package sets decide while loading
# (automatic exclusions, post_import blocks) reaches the catalog. One shared
# workspace for the run (RealRockWorkspace.shared): nothing here changes it.
RSpec.describe "the real Rock package sets" do
  before(:all) do
    need_fixture(RealRockWorkspace.available?, RealRockWorkspace.skip_reason)
    @workspace = RealRockWorkspace.shared
  end

  def spec_text(select)
    <<~YAML
      release: rock
      workspace: #{@workspace.root}
      select: [#{select.join(', ')}]
      targets: { bookworm: [amd64] }
    YAML
  end

  def catalog_of(root = @workspace.root)
    with_specs("rock" => spec_text(%w[typelib]).sub(@workspace.root, root)) do |dir|
      Relspec::Catalog::ReleaseCatalog.load(Relspec::ReleaseSpec.resolve(File.join(dir, "rock.yml"))).catalog
    end
  end

  it "honours rock.core's automatic exclusion of ocl (USE_OCL is false)" do
    expect(catalog_of.excluded).to include("ocl")
    with_specs("rock" => spec_text(%w[ocl])) do |dir|
      run = relspec("plan", File.join(dir, "rock.yml"))
      expect(run.exit_code).to eq(1)
      expect(run.stderr).to include("error[excluded-package]").and include("ocl is selected but excluded")
    end
  end

  it "makes gui/vizkit unavailable on bookworm through qtruby (osdeps for Ubuntu and Gentoo only), with the cause" do
    expect(catalog_of.package("gui/vizkit").os_dependencies_for("bookworm").other_os).to eq(["qtruby"])
    with_specs("rock" => spec_text(%w[gui/vizkit])) do |dir|
      run = relspec("plan", File.join(dir, "rock.yml"))
      expect(run.exit_code).to eq(1)
      expect(run.stderr).to include("error[unavailable-selection]: gui/vizkit is selected, but cannot be built on " \
                                    "bookworm: it needs the osdep qtruby, which the osdeps files define for other systems only")
      expect(run.stderr).not_to include("unknown-osdep")
    end
  end

  it "runs the post_import blocks: typelib depends on the castxml importer rock.core chooses" do
    os = catalog_of.package("typelib").os_dependencies_for("bookworm")
    expect(os.apt).to include("castxml")
    expect(os.apt).not_to include("gccxml")
  end

  it "keeps the environment the package sets give typelib, relative to its prefix" do
    # orocos.toolchain's definition, the importer its post_import block
    # chose, and what rock.core adds to every package
    expect(catalog_of.package("typelib").environment)
      .to eq([{ "type" => "set", "name" => "TYPELIB_PLUGIN_PATH", "values" => ["$PREFIX/lib/typelib"] },
              { "type" => "set", "name" => "TYPELIB_CXX_LOADER", "values" => ["castxml"] },
              { "type" => "add_path", "name" => "QT_PLUGIN_PATH", "values" => ["$PREFIX/lib/qt"] }])
  end

  # `pkg.define 'SISL_PREFIX', package('external/sisl').prefix`: in the default layout every
  # prefix is $AUTOPROJ_ROOT/install, yet the catalog names external/sisl's (the release's, in debian/rules)
  it "keeps a define naming external/sisl's prefix as a reference to external/sisl" do
    expect(catalog_of.package("base/types").defines).to include("SISL_PREFIX" => "${prefix:external/sisl}",
                                                                "USE_SISL" => "OFF")
  end

  it "carries rock.core's import patch of tools/class_loader with its level and text" do
    catalog = catalog_of
    patches = catalog.package("tools/class_loader").patches
    expect(patches.map { |patch| [patch.path, patch.level] })
      .to eq([[".autoproj/remotes/github__rock_core_package_set_git/patches/class_loader_pkgconfig.patch", 0]])
    expect(patches.first.content).to include("+Requires: console_bridge @PKGCONFIG_REQUIRES@")
    expect(catalog.package("base/cmake").patches).to eq([])
    # a snapshot carries the patch byte for byte, and autoproj's exclusion reasons
    Dir.mktmpdir("relspec-real-snapshot") do |dir|
      path = File.join(dir, "catalog.yml")
      File.write(path, Relspec::Catalog::SnapshotSource.dump(catalog))
      expect(Relspec::Catalog::SnapshotSource.load(path)).to eq(catalog)
      expect(Relspec::Catalog::SnapshotSource.load(path).exclusion_reasons).to include("ocl" => /USE_OCL/)
    end
  end

  it "gives oroGen packages the generator words autoproj would, from both package sets" do
    # orocos.toolchain turns CORBA on (rtt_corba_implementation omniorb);
    # rock.core, with USE_OCL off: type export 'used' and --no-rtt-scripting,
    # metadata_support on master, --import=std for all but std itself
    expect(catalog_of.package("base/orogen/std").orogen_arguments)
      .to eq(%w[--corba --extensions=metadata_support --no-rtt-scripting --transports=corba,mqueue,typelib
                --type-export-policy=used std.orogen])
    expect(catalog_of.package("base/orogen/types").orogen_arguments)
      .to eq(%w[--corba --extensions=metadata_support --import=std --no-rtt-scripting
                --transports=corba,mqueue,typelib --type-export-policy=used base.orogen])
    expect(catalog_of.package("typelib").orogen_arguments).to eq([])
  end

  it "runs them without writing into the workspace (rtt's block deletes a generated file)" do
    Dir.mktmpdir("relspec-real-rock-copy") do |base|
      copy = File.join(base, "workspace")
      FileUtils.cp_r(@workspace.root, copy)
      stale = File.join(copy, "src", "tools", "rtt", "rtt", "plugin", "pluginpath.cpp")
      File.write(stale, "// left by an old RTT build\n")
      # in its own process: a package set's init.rb requires its Ruby files
      # once per process, from the first workspace loaded there
      run = relspec("catalog", "export", copy, "--targets", "bookworm", "-o", File.join(base, "catalog.yml"))
      expect(run.exit_code).to eq(0), run.stderr
      expect(YAML.safe_load(File.read(File.join(base, "catalog.yml"))).fetch("packages")).to include("rtt")
      expect(File.read(stale)).to eq("// left by an old RTT build\n")
    end
  end

  # typelib and utilrb need the gem facets, which bookworm lacks: it is
  # packaged from gem_source. The facets here is a stand-in whose runtime
  # dependencies are the kinds the real layout's gems have: Ruby's default
  # gems (bookworm's libruby3.1 provides ruby-date, ruby-logger, … at their
  # versions), gems Debian names irregularly (rake, yard, ruby-concurrent)
  # and a version-constrained one Debian has (ruby-pastel 0.8.0). None of
  # them may become a package or a false note; this machine's apt lists
  # stand for bookworm's archive.
  it "takes Ruby's default gems and Debian's irregularly named gems from the distribution" do
    with_specs("rock" => <<~YAML) do |dir, root|
      release: rock
      workspace: #{@workspace.root}
      select: [typelib, tools/metaruby]
      targets: { bookworm: [amd64] }
      distributions: { bookworm: { archive: { host: true } } }
      gem_source: ../gems
    YAML
      GemBuilder.build(File.join(root, "gems"), "facets", "3.1.0",
                       dependencies: { "pastel" => "~> 0.8", "date" => ">= 0", "io-console" => ">= 0.5", "logger" => ">= 1.4",
                                       "rake" => ">= 12.0", "yard" => ">= 0.9", "concurrent-ruby" => "~> 1.1" })
      run = relspec("plan", File.join(dir, "rock.yml"))
      expect(run.exit_code).to eq(0), run.stderr
      expect(run.stdout).to start_with("rock: 4 packages on 1 targets")
      built = run.stdout[%r{^builds on bookworm/amd64:\n(.*?)\n\n}m, 1].lines.grep(/^  \S/).map { |line| line.split.first }
      expect(built).to eq(%w[facets tools/metaruby typelib utilrb])
      expect(run.stdout).to include("the bookworm archive has no ruby-facets: gem facets is packaged here")
      expect(run.stdout).not_to include("lacks")
    end
  end

  it "reports every gem missing from an offline gem_source in one run, with how to fetch it" do
    with_specs("rock" => <<~YAML) do |dir, root|
      release: rock
      workspace: #{@workspace.root}
      select: [typelib, tools/orocos.rb]
      leave_out: [{ match: tools/pocolog, reason: not among the repositories of ../shared }]
      targets: { bookworm: [amd64] }
      distributions: { bookworm: { archive: { host: true } } }
      gem_source: ../gems
    YAML
      FileUtils.mkdir_p(File.join(root, "gems"))
      run = relspec("plan", File.join(dir, "rock.yml"))
      expect(run.exit_code).to eq(1)
      # bookworm lacks facets and rice, and has rake-compiler only at 1.2.1 (Rock asks for <0.9.0)
      expect(run.stderr.scan(/error\[gem-unresolvable\]: no version of gem (\S+)/).flatten).to eq(%w[facets rake-compiler rice])
      expect(run.stderr).to include("hint: fetch it into ../gems: `gem fetch rake-compiler -v '< 0.9.0'`; with the gems " \
                                    "it needs: `gem install --install-dir <dir> --no-document rake-compiler -v '< 0.9.0'`")
      expect(run.stderr).not_to match(/\.rb:\d+:in /)
    end
  end
end
