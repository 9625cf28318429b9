# frozen_string_literal: true

require "spec_helper"
require "relspec/catalog/release_catalog"
require_relative "../../support/real_rock_workspace"

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

  it "runs the post_import blocks: typelib depends on the castxml importer rock.core chooses" do
    os = catalog_of.package("typelib").os_dependencies_for("bookworm")
    expect(os.apt).to include("castxml")
    expect(os.apt).not_to include("gccxml")
  end

  it "runs them without writing into the workspace (rtt's block deletes a generated file)" do
    Dir.mktmpdir("relspec-real-rock-copy") do |base|
      copy = File.join(base, "workspace")
      FileUtils.cp_r(@workspace.root, copy)
      stale = File.join(copy, "src", "tools", "rtt", "rtt", "plugin", "pluginpath.cpp")
      File.write(stale, "// left by an old RTT build\n")
      expect(catalog_of(copy).package("rtt")).not_to be_nil
      expect(File.read(stale)).to eq("// left by an old RTT build\n")
    end
  end
end
