# frozen_string_literal: true

require "tmpdir"
require "relspec/release_specs/effective"
require "relspec/release_specs/origin"

# The effective spec read as typed values: in memory, no file but a temporary
# folder for the one rule that asks the file system (a local repository path
# is preferred only when it exists).
RSpec.describe "ReleaseSpec typed values" do
  # Origin only asks its file for the path here.
  let(:spec_file) { Struct.new(:path) }

  def effective(values, repository_file: "/specs/demo.yml")
    origins = values.key?("repository") ? { "repository" => Relspec::ReleaseSpec::Origin.new(spec_file.new(repository_file), ["repository"]) } : {}
    Relspec::ReleaseSpec::EffectiveSpec.new(values, origins)
  end

  describe Relspec::ReleaseSpec::RepositoryEntry do
    it "resolves path and keyring against the folder of the spec that wrote them" do
      entry = effective({ "repository" => { "path" => "../repo", "keyring" => "k.gpg", "trusted" => true,
                                            "sign_with" => "ABCD", "debug_symbols" => true } }).repository
      expect(entry).to have_attributes(path: "/repo", keyring: "/specs/k.gpg", trusted: true, sign_with: "ABCD", url: nil,
                                       debug_symbols: true)
      expect(entry).to be_frozen
    end

    it "is nil without a repository and treats a missing trusted or debug_symbols as false" do
      expect(effective({}).repository).to be_nil
      expect(Relspec::ReleaseSpec::RepositoryEntry.from({ "url" => "http://127.0.0.1/r" }, base: "/"))
        .to have_attributes(trusted: false, debug_symbols: false)
      expect(Relspec::ReleaseSpec::RepositoryEntry.from("nonsense", base: "/")).to be_nil
    end

    it "reads from the local path when it exists or when there is no url, else from the url" do
      Dir.mktmpdir do |dir|
        both = ->(path) { Relspec::ReleaseSpec::RepositoryEntry.from({ "path" => path, "url" => "http://127.0.0.1/r" }, base: dir) }
        expect(both.call(".").location).to eq(dir)
        expect(both.call("missing").location).to eq("http://127.0.0.1/r")
        expect(Relspec::ReleaseSpec::RepositoryEntry.from({ "path" => "missing" }, base: dir).location).to eq(File.join(dir, "missing"))
      end
    end

    it "publishes into its path even before the path exists" do
      entry = Relspec::ReleaseSpec::RepositoryEntry.from({ "path" => "missing", "url" => "http://127.0.0.1/r" }, base: "/nowhere")
      expect(entry.own_location).to eq("/nowhere/missing")
      expect(Relspec::ReleaseSpec::RepositoryEntry.from({ "url" => "http://127.0.0.1/r" }, base: "/").own_location)
        .to eq("http://127.0.0.1/r")
    end
  end

  describe Relspec::ReleaseSpec::Prefixes do
    it "takes the defaults for keys the spec leaves out" do
      prefixes = effective({}).prefixes
      expect(prefixes).to have_attributes(install_prefix: "/opt/rock", separate_prefixes: true, package_prefix: "rock")
      expect(prefixes.install_dir("demo", "rock-demo-base-types")).to eq("/opt/rock/demo/rock-demo-base-types")
    end

    it "keeps separate_prefixes: false and a shared prefix" do
      prefixes = effective({ "separate_prefixes" => false, "install_prefix" => "/opt/x", "package_prefix" => "x" }).prefixes
      expect(prefixes).to have_attributes(install_prefix: "/opt/x", separate_prefixes: false, package_prefix: "x")
      expect(prefixes.install_dir("demo", "x-demo-a")).to eq("/opt/x/demo")
    end
  end

  describe Relspec::ReleaseSpec::BlacklistEntry do
    it "is a pattern, a reason and its place in the spec" do
      entries = effective({ "blacklist" => [{ "match" => "base/types", "reason" => "old API" }, { "match" => "drivers/*" }] }).blacklist
      expect(entries.map(&:index)).to eq([0, 1])
      expect(entries.map(&:reason)).to eq(["old API", nil])
      expect(entries[1].match?("drivers/camera")).to be(true)
      expect(entries[0].match?("base/types2")).to be(false)
      expect(entries).to all(be_frozen)
    end
  end

  describe Relspec::ReleaseSpec::Pin do
    it "is a ref and a value, given back in the spec's form" do
      pins = effective({ "pins" => { "base/types" => { "tag" => "v2.0.0" } } }).pins
      expect(pins.fetch("base/types")).to have_attributes(ref: "tag", value: "v2.0.0")
      expect(pins.fetch("base/types").to_h).to eq("tag" => "v2.0.0")
      expect(effective({}).pins).to eq({})
    end
  end

  describe Relspec::ReleaseSpec::LeaveOut do
    let(:spec) do
      effective({ "leave_out" => [{ "match" => "gui/**", "reason" => "qt4", "targets" => %w[bookworm bookworm] },
                                  { "match" => "bad[", "reason" => "typo", "targets" => ["bookwork"] },
                                  { "match" => "tools/x", "reason" => "everywhere" }] })
    end

    it "matches the first parseable entry that applies to the codename" do
      expect(spec.leave_out.entries.map(&:index)).to eq([0, 2])
      expect(spec.leave_out.match("gui/vizkit", "bookworm").reason).to eq("qt4")
      expect(spec.leave_out.match("gui/vizkit", "bionic")).to be_nil
      expect(spec.leave_out.match("tools/x", "bionic").codenames).to be_nil
    end

    it "gives the rules every entry's codenames as written, in place (leave_out_codenames)" do
      expect(spec.leave_out_codenames).to eq([%w[bookworm bookworm], ["bookwork"], []])
      expect(effective({}).leave_out_codenames).to eq([])
    end
  end

  it "reads the other keys with their defaults" do
    spec = effective({ "parent" => "base", "workspace" => "../ws", "maintainer" => "M <m@example.org>" })
    expect(spec).to have_attributes(parents: ["base"], workspace: "../ws", maintainer: "M <m@example.org>", select: nil,
                                    gems: {}, gem_source: "https://rubygems.org")
    expect(effective({ "parent" => %w[a b], "gems" => { "rake" => "13.0" } })).to have_attributes(parents: %w[a b],
                                                                                                  gems: { "rake" => "13.0" })
  end

  describe Relspec::ReleaseSpec::Archive do
    let(:values) do
      { "distributions" => { "bookworm" => { "archive" => { "path" => "../debian", "trusted" => true, "components" => %w[main contrib] } } } }
    end

    it "is the distribution's archive as a frozen, typed value" do
      archive = effective(values).distributions.fetch("bookworm").archive
      expect(archive).to have_attributes(path: "../debian", url: nil, trusted: true, components: %w[main contrib], host?: false)
      expect([archive, archive.components, archive.components.first, archive.path]).to all(be_frozen)
      expect(archive.read_components).to eq(%w[main contrib])
      expect(archive.repository_entry("/specs")).to have_attributes(path: "/debian", trusted: true)
      expect(archive.to_h).to eq(values.dig("distributions", "bookworm", "archive"))
    end

    it "reads main when no components are written, and knows host: true" do
      archive = Relspec::ReleaseSpec::Archive.from("host" => true)
      expect([archive.host?, archive.read_components]).to eq([true, ["main"]])
      expect(Relspec::ReleaseSpec::Archive.from(nil)).to be_nil
      expect(Relspec::ReleaseSpec::Archive.from("nonsense")).to be_nil
      expect(Relspec::ReleaseSpec::Archive.from(archive)).to equal(archive)
    end
  end

  describe Relspec::ReleaseSpec::EffectiveSpec do
    it "is frozen all the way down, without freezing the caller's own values" do
      blacklist = [{ "match" => +"base/types", "reason" => +"new API" }]
      spec = effective({ "release" => +"demo", "blacklist" => blacklist, "targets" => { "bookworm" => ["amd64"] } })
      [spec.values, spec["release"], spec["blacklist"], spec["blacklist"].first, spec["blacklist"].first["reason"],
       spec.targets, spec.targets["bookworm"]].each { |value| expect(value).to be_frozen }
      expect(blacklist.first["reason"]).not_to be_frozen
      expect { spec["blacklist"].first["reason"] << "!" }.to raise_error(FrozenError)
    end
  end
end
