# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/osdeps/reader"
require "relspec/osdeps/operating_system"

# The one reader of releases.yml and the osdeps files (select, package-set,
# mirror, the package set's init.rb): a value or the reason.
RSpec.describe Relspec::Osdeps::Reader do
  def reason(reading)
    expect(reading.value).to be_nil
    reading.reason
  end

  it "reads plain YAML only" do
    expect(described_class.yaml("a: 1\n").value).to eq("a" => 1)
    expect(described_class.yaml("", empty: {}).value).to eq({})
    expect(reason(described_class.yaml("a: &x 1\nb: *x\n"))).to start_with("is not plain YAML (")
    expect(reason(described_class.yaml("a: !ruby/object:Object {}\n"))).to start_with("is not plain YAML (")
  end

  it "reads releases.yml as release => parent, leaving default out and checking every name" do
    data = { "default" => { "repo_url" => "http://x" }, "base" => nil, "child" => { "depends_on" => "base" } }
    expect(described_class.releases(data).value).to eq("base" => nil, "child" => "base")
    expect(reason(described_class.releases([]))).to eq("is not a mapping of releases")
    expect(reason(described_class.releases("../x" => nil))).to eq('"../x": "../x" is not a release name')
    expect(reason(described_class.releases("a" => { "depends_on" => "-o" }))).to eq('"a": "-o" is not a release name')
    expect(reason(described_class.releases("a" => "b"))).to eq('"a": is not a mapping')
  end

  it "walks the lineage root first, refusing a cycle and a parent not held" do
    expect(described_class.lineage({ "a" => nil, "b" => "a", "c" => "b" }, "c").value).to eq(%w[a b c])
    expect(reason(described_class.lineage({ "a" => "b", "b" => "a" }, "a"))).to eq("depends_on cycle through a")
    expect(reason(described_class.lineage({ "b" => "a" }, "b"))).to eq("b depends on a, which it does not hold")
  end

  it "checks every entry of a file relspec ships, naming the packages, by name" do
    good = { "base/cmake" => { "debian" => { "12,bookworm" => "rock-r-base-cmake" } } }
    expect(described_class.osdeps_problems(good)).to eq([])
    bad = good.merge("z" => { "debian" => { "12,bookworm" => "-oX=y" } }, "a" => { "debian" => "x" }, "m" => nil)
    expect(described_class.osdeps_problems(bad))
      .to eq(["a: is not a mapping of OS types", "m: is not a mapping of OS types",
              'z: "-oX=y" is not a Debian package name (lowercase letters, digits, + - ., not starting with - or .)'])
    expect(described_class.osdeps_problems("x")).to eq(["is not a mapping of packages"])
  end

  def system(names, versions)
    Relspec::Osdeps::OperatingSystem.new(names, versions)
  end

  it "resolves a file for a system, Ubuntu's type key as Debian's, checking each name it gives" do
    data = { "a" => { "ubuntu,debian" => { "20.04,focal" => "rock-a" } }, "b" => { "debian" => { "12,bookworm" => "rock-b" } },
             "gem" => { "gem" => "x_y" }, "old" => { "ubuntu" => { "16.04,xenial" => %w[ruby-ffi libffi-dev] } } }
    expect(described_class.resolve(data, system(%w[ubuntu debian], %w[20.04 focal])).value).to eq("a" => "rock-a")
    expect(described_class.resolve(data, system(%w[debian], %w[bookworm])).value).to eq("b" => "rock-b")
    expect(reason(described_class.resolve(data, system(%w[ubuntu], %w[xenial]))))
      .to eq('old: ["ruby-ffi", "libffi-dev"] is not a Debian package name (lowercase letters, digits, + - ., not starting with - or .)')
    expect(reason(described_class.resolve([], system(%w[debian], %w[bookworm])))).to eq("is not a mapping of packages")
    # autoproj's list form, in the published Rock files: each name checked
    expect(described_class.resolve(data, system(%w[ubuntu], %w[xenial]), lists: true).value)
      .to eq("old" => %w[ruby-ffi libffi-dev])
    data["old"]["ubuntu"]["16.04,xenial"] = ["ruby-ffi", "-o"]
    expect(reason(described_class.resolve(data, system(%w[ubuntu], %w[xenial]), lists: true))).to start_with('old: "-o" is not')
  end
end
