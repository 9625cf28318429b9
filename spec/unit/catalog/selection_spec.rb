# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog"
require "relspec/catalog/selection"

# autoproj's spreading of unavailability, on a catalog made in memory:
# maps is excluded by its package set, core requires it, app requires
# core; legacy needs an osdep defined for other systems only.
RSpec.describe Relspec::Catalog::Selection do
  def package(name, dependencies: [], optional: [], other_os: [])
    os = { "bookworm" => Relspec::Catalog::OsDependencies.build(other_os: other_os) }
    Relspec::Catalog::Package.new(name: name, package_set: "set", build_type: "cmake", commit_time: "2020-01-01T00:00:00Z",
                                  source_dir: "src/#{name}", dependencies: dependencies, optional_dependencies: optional,
                                  os_dependencies: os, vcs: Relspec::Catalog::Vcs.new(type: "git", url: "u").freeze)
  end

  let(:catalog) do
    packages = [package("maps"), package("core", dependencies: ["maps"]), package("app", dependencies: ["core"]),
                package("viewer", optional: ["maps"]), package("legacy", other_os: ["qtruby"])]
    Relspec::Catalog.new(packages: packages.to_h { |pkg| [pkg.name, pkg] }, codenames: ["bookworm"],
                         metapackages: { "weak" => %w[app viewer], "strong" => %w[app viewer], "all_gone" => %w[app] },
                         excluded: ["maps"], exclusion_reasons: { "maps" => "needs a newer PCL" },
                         weak_metapackages: %w[all_gone weak])
  end

  def resolve(select)
    described_class.resolve(catalog, select, codename: "bookworm", workspace: "/ws")
  end

  def messages(select)
    resolve(select)
    raise "expected InvalidInput"
  rescue Relspec::InvalidInput => e
    e.diagnostics.map(&:message)
  end

  it "drops a weak metapackage's packages that need an excluded one, each naming its nearest reason" do
    selection = resolve(["weak"])
    expect(selection.names).to eq(["viewer"])
    expect(selection.unavailable.transform_values { |reason| reason.to_h.compact })
      .to eq("app" => { dependency: "core" }, "core" => { dependency: "maps" }, "maps" => { excluded: "needs a newer PCL" })
  end

  it "refuses a strong metapackage with such a package, and a weak one with nothing left, as autoproj does" do
    expect(messages(["strong"])).to eq(["strong is selected, but its package app cannot be built on bookworm: it requires " \
                                        "core, which requires maps, which is excluded (needs a newer PCL)"])
    expect(messages(["all_gone"]).first).to start_with("all_gone is selected, but its package app cannot be built")
  end

  it "refuses a selected package that needs an osdep of other systems, naming the osdep; the layout says so" do
    expect(messages(["legacy"])).to eq(["legacy is selected, but cannot be built on bookworm: it needs the osdep qtruby, " \
                                        "which the osdeps files define for other systems only"])
    layout = Relspec::Catalog.new(packages: catalog.packages, layout: ["legacy"], codenames: ["bookworm"])
    expect { described_class.resolve(layout, nil, codename: "bookworm", workspace: "/ws") }
      .to raise_error(Relspec::InvalidInput) { |e| expect(e.diagnostics.first.message).to start_with("legacy is in the layout, but") }
  end

  it "treats a `leave_out` as a gap, not an error, even on the way to an exclusion" do
    entry = Struct.new(:pattern, :reason).new(/core/, "later")
    selection = described_class.resolve(catalog, ["app"], codename: "bookworm", workspace: "/ws",
                                                          leave_out: ->(name) { name == "core" ? entry : nil })
    expect(selection.names).to eq([])
    expect(selection.unavailable.keys).to eq(%w[app core])
  end
end
