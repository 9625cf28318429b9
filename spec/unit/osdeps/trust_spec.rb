# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/osdeps/trust"

# What the package set accepts from a repository (issue 33), value by value.
RSpec.describe Relspec::Osdeps::Trust do
  describe ".debian_name" do
    it "accepts Debian package names" do
      expect(%w[rock-demo-base-base-cmake libc6 g++ ruby2.7].map { |name| described_class.debian_name(name) }).to all(be_nil)
    end

    it "refuses options, spaces, shell and apt syntax, paths, upper case and non-strings" do
      ["-oDPkg::Pre-Invoke::=x", "a b", "a;b", "$(x)", "a=1.0", "../x", "Rock", "a", ".a", "a/b", nil, 3].each do |name|
        expect(described_class.debian_name(name)).to include("is not a Debian package name"), name.inspect
      end
    end
  end

  describe ".url" do
    it "accepts plain http(s) URLs" do
      %w[http://127.0.0.1:8000/demo-base https://example.org/rock-releases/demo-base/].each do |url|
        expect(described_class.url(url)).to be_nil
      end
    end

    it "refuses other schemes, newlines, spaces and apt option brackets" do
      ["file:///srv/a", "http://a/b\ndeb [trusted=yes] http://c/d", "http://a/b c", "http://a/[x]", "http://", nil].each do |url|
        expect(described_class.url(url)).to include("is not a plain http(s) URL"), url.inspect
      end
    end
  end

  describe ".apt_entry" do
    it "accepts a signed entry with a key of the package set, and a trusted one without key" do
      expect(described_class.apt_entry("url" => "http://a/r", "trusted" => false, "key" => "keys/r.gpg")).to be_nil
      expect(described_class.apt_entry("url" => "http://a/r", "trusted" => true)).to be_nil
    end

    it "refuses trusted=yes unless the entry says trusted: true, keys outside keys/, and both at once" do
      expect(described_class.apt_entry("url" => "http://a/r", "trusted" => "yes")).to include("does not say trusted: true")
      expect(described_class.apt_entry("url" => "http://a/r")).to include("does not say trusted: true")
      expect(described_class.apt_entry("url" => "http://a/r", "key" => "../../etc/hostname"))
        .to include("is not a keys/<release>.gpg")
      expect(described_class.apt_entry("url" => "http://a/r", "trusted" => true, "key" => "keys/r.gpg"))
        .to include("one or the other")
      expect(described_class.apt_entry("http://a/r")).to eq("is not a mapping of url, trusted and key")
    end
  end

  describe ".environment" do
    it "accepts allowed variables with paths below the prefix" do
      expect(described_class.environment("PATH", { type: :add_path, values: ["/opt/rock/r/p/bin"] })).to be_nil
      expect(described_class.environment("CMAKE_PREFIX_PATH", { type: :set, values: "/opt/rock/r/p" })).to be_nil
    end

    it "refuses other variables, other types, paths outside the prefix or climbing out of it" do
      expect(described_class.environment("LD_PRELOAD", { type: :set, values: ["/opt/rock/x.so"] }))
        .to include("is not a variable")
      expect(described_class.environment("PATH", { type: :eval, values: ["/opt/rock/r"] })).to include("the type :eval")
      ["/usr/lib", "/opt/rock/../tmp", "/opt/rockx/lib", "/opt/rock/a:/tmp", "relative", 3].each do |value|
        expect(described_class.environment("LD_LIBRARY_PATH", { type: :add_path, values: [value] }))
          .to include("is not a path below /opt/rock"), value.inspect
      end
      expect(described_class.environment("PATH", "/opt/rock/x")).to include("is not a mapping")
    end
  end

  describe ".environment of the settings the real Rock package sets give packages" do
    it "accepts one plain word set (typelib's importer, RTT's target, orocos.rb's name service)" do
      expect(described_class.environment("TYPELIB_CXX_LOADER", { type: :set, values: ["castxml"] })).to be_nil
      expect(described_class.environment("OROCOS_TARGET", { type: :set, values: "gnulinux" })).to be_nil
      expect(described_class.environment("ORBInitRef", { type: :set, values: ["NameService=corbaname::127.0.0.1"] }))
        .to be_nil
      expect(described_class.environment("QT_PLUGIN_PATH", { type: :add_path, values: ["/opt/rock/r/p/lib/qt"] })).to be_nil
    end

    it "refuses shell syntax, several words, or adding to them" do
      ["castxml; reboot", "a b", "$(id)", "", "x\ny"].each do |value|
        expect(described_class.environment("TYPELIB_CXX_LOADER", { type: :set, values: [value] }))
          .to include("is not one plain word"), value.inspect
      end
      expect(described_class.environment("OROCOS_TARGET", { type: :add, values: ["gnulinux"] }))
        .to eq("OROCOS_TARGET: is set (one word), not added to")
    end
  end

  describe ".environment_file" do
    it "refuses a file whose real path is outside the prefix" do
      Dir.mktmpdir do |dir|
        File.write(File.join(dir, "env.yml"), "")
        expect(described_class.environment_file(File.join(dir, "env.yml"))).to eq("is #{File.realpath(dir)}/env.yml, outside /opt/rock")
      end
    end
  end

  it "checks release names" do
    expect(described_class.release_name("demo-base")).to be_nil
    expect(described_class.release_name("../etc")).to eq("\"../etc\" is not a release name")
  end
end
