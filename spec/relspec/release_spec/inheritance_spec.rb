# frozen_string_literal: true

require "spec_helper"

# The inheritance rules of DESIGN §4 / docs/spec-reference.md, one example each.
RSpec.describe "spec inheritance" do
  def effective(files, name)
    with_specs(files) do |dir|
      resolution = resolve(dir, name)
      expect(resolution.errors).to be_empty, resolution.diagnostics.join("\n")
      return resolution.effective
    end
  end

  let(:root) do
    <<~YAML
      release: root
      targets: { bionic: [amd64, arm64] }
      install_prefix: /opt/root
      separate_prefixes: false
      package_prefix: rt
      maintainer: Root Team <root@example.org>
      distributions: { duke: { type: debian, labels: [15, duke, default] } }
      gems: { rice: "4.0.2" }
      pins: { base/types: { commit: aaaaaaa }, base/cmake: { tag: v1 } }
      blacklist: [{ match: base/types, reason: root rebuilds it }]
      description: the root
      workspace: ../ws
      select: [rock.core]
      repository: { path: /srv/root, trusted: true }
    YAML
  end

  it "orders ancestors depth first, parents in written order, each once" do
    files = {
      "a" => "release: a\nparent: [b, c]\n",
      "b" => "release: b\nparent: d\n",
      "c" => "release: c\nparent: d\n",
      "d" => "release: d\ntargets: { bionic: [amd64] }\n"
    }
    expect(effective(files, "a").ancestors).to eq(%w[b d c])
  end

  it "reports a cycle with the whole chain at the parent entry that closes it" do
    files = {
      "a" => "release: a\nparent: b\ntargets: { bionic: [amd64] }\n",
      "b" => "release: b\nparent: [root, a]\n",
      "root" => root
    }
    with_specs(files) do |dir|
      errors = resolve(dir, "a").errors
      expect(errors.map(&:message)).to eq(["parent cycle: a -> b -> a"])
      expect(errors.first.location.to_s).to eq("#{dir}/b.yml:2:16")
    end
  end

  it "reports an unknown parent with a suggestion" do
    with_specs("child" => "release: child\nparent: roott\n", "root" => root) do |dir|
      errors = resolve(dir, "child").errors
      expect(errors.map(&:rule)).to eq(["unknown-parent"])
      expect(errors.first.hint).to eq('did you mean "root"?')
    end
  end

  it "takes targets, prefixes, maintainer, distributions and gems from the parent" do
    spec = effective({ "root" => root, "child" => "release: child\nparent: root\n" }, "child")
    expect(spec["targets"]).to eq("bionic" => %w[amd64 arm64])
    expect(spec["install_prefix"]).to eq("/opt/root")
    expect(spec["separate_prefixes"]).to be(false)
    expect(spec["package_prefix"]).to eq("rt")
    expect(spec["maintainer"]).to eq("Root Team <root@example.org>")
    expect(spec["distributions"]).to eq("duke" => { "type" => "debian", "labels" => %w[15 duke default] })
    expect(spec["gems"]).to eq("rice" => "4.0.2")
    expect(spec.origin("targets").location.file).to end_with("root.yml")
  end

  it "lets the child's own values replace the parent's as a whole" do
    child = "release: child\nparent: root\ntargets: { buster: [amd64] }\ngems: { qtbindings: '4.8.6' }\n"
    spec = effective({ "root" => root, "child" => child }, "child")
    expect(spec["targets"]).to eq("buster" => ["amd64"])
    expect(spec["gems"]).to eq("qtbindings" => "4.8.6")
  end

  it "inherits through several levels" do
    files = { "root" => root, "mid" => "release: mid\nparent: root\npackage_prefix: mid\n",
              "leaf" => "release: leaf\nparent: mid\n" }
    spec = effective(files, "leaf")
    expect(spec["package_prefix"]).to eq("mid")
    expect(spec["install_prefix"]).to eq("/opt/root")
  end

  it "takes a value from the first parent that has one" do
    files = {
      "p1" => "release: p1\ntargets: { bionic: [amd64] }\n",
      "p2" => "release: p2\ntargets: { buster: [amd64] }\npackage_prefix: p2\n",
      "child" => "release: child\nparent: [p1, p2]\n"
    }
    spec = effective(files, "child")
    expect(spec["targets"]).to eq("bionic" => ["amd64"])
    expect(spec["package_prefix"]).to eq("p2")
  end

  it "merges pins, the child winning over parents and earlier parents over later ones" do
    files = {
      "p1" => "release: p1\ntargets: { bionic: [amd64] }\npins: { a/x: { tag: p1 } }\n",
      "p2" => "release: p2\npins: { a/x: { tag: p2 }, a/y: { tag: p2 }, a/z: { tag: p2 } }\n",
      "child" => "release: child\nparent: [p1, p2]\npins: { a/z: { commit: abcdef0 } }\n"
    }
    spec = effective(files, "child")
    expect(spec["pins"]).to eq("a/x" => { "tag" => "p1" }, "a/y" => { "tag" => "p2" }, "a/z" => { "commit" => "abcdef0" })
    expect(spec.pin_origin("a/y").location.file).to end_with("p2.yml")
    expect(spec.pin_origin("a/z").location.file).to end_with("child.yml")
  end

  it "never inherits blacklist, description, workspace, select or repository" do
    spec = effective({ "root" => root, "child" => "release: child\nparent: root\n" }, "child")
    expect(spec.values.keys).not_to include("blacklist", "description", "workspace", "select", "repository")
  end

  it "uses built-in defaults when no spec sets a value" do
    spec = effective({ "solo" => "release: solo\ntargets: { bionic: [amd64] }\n" }, "solo")
    expect(spec.to_h.slice("install_prefix", "separate_prefixes", "package_prefix", "gems"))
      .to eq("install_prefix" => "/opt/rock", "separate_prefixes" => true, "package_prefix" => "rock", "gems" => {})
    expect(spec.origin("package_prefix")).to be_default
    expect(spec.values).not_to have_key("maintainer")
  end

  it "treats external releases as leaf ancestors that can provide targets and prefixes" do
    child = <<~YAML
      release: child
      parent: master-20.06
      external:
        master-20.06:
          url: https://example.org/rock-releases/master-20.06
          trusted: true
          package_prefix: rock
          targets: { bionic: [amd64] }
    YAML
    spec = effective({ "child" => child }, "child")
    expect(spec.ancestors).to eq(["master-20.06"])
    expect(spec["targets"]).to eq("bionic" => ["amd64"])
    expect(spec.origin("targets").to_s).to match(/child\.yml:\d+:\d+/)
  end

  it "identifies an external release declared by two specs of a diamond by its name" do
    external = "external: { ext: { path: /srv/ext, trusted: true } }\n"
    files = { "a" => "release: a\nparent: ext\n#{external}targets: { bionic: [amd64] }\n",
              "b" => "release: b\nparent: ext\n#{external}targets: { bionic: [amd64] }\n",
              "child" => "release: child\nparent: [a, b]\n" }
    expect(effective(files, "child").ancestors).to eq(%w[a ext b])
    files["b"] = files["b"].sub("/srv/ext", "/srv/other")
    with_specs(files) do |dir|
      errors = resolve(dir, "child").errors
      expect(errors.map(&:rule)).to eq(["conflicting-external"])
      expect(errors.first.message).to match(/external release "ext" is declared differently here and in .*a\.yml/)
    end
  end

  it "does not follow parents of an external release (it has none)" do
    child = "release: child\nparent: [ext, root]\nexternal: { ext: { path: /srv/ext, trusted: true } }\n"
    spec = effective({ "child" => child, "root" => root }, "child")
    expect(spec.ancestors).to eq(%w[ext root])
    expect(spec["targets"]).to eq("bionic" => %w[amd64 arm64])
  end

  it "checks target codenames against inherited distribution definitions" do
    files = { "root" => root, "child" => "release: child\nparent: root\ntargets: { duke: [amd64] }\n" }
    expect(effective(files, "child")["targets"]).to eq("duke" => ["amd64"])
    files["lonely"] = "release: lonely\ntargets: { duke: [amd64] }\n"
    with_specs(files) do |dir|
      expect(resolve(dir, "lonely").errors.map(&:rule)).to eq(["unknown-distribution"])
    end
  end

  it "reports the errors of an ancestor's file when checking its child" do
    files = { "root" => "release: root\ntargets: { bionic: [amd46] }\n", "child" => "release: child\nparent: root\n" }
    with_specs(files) do |dir|
      errors = resolve(dir, "child").errors
      expect(errors.map { |e| [e.rule, File.basename(e.location.file)] }).to eq([%w[unknown-architecture root.yml]])
    end
  end

  it "requires targets somewhere in the hierarchy" do
    with_specs("a" => "release: a\n") do |dir|
      expect(resolve(dir, "a").errors.map(&:rule)).to eq(["missing-targets"])
    end
  end
end
