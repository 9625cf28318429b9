# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/debhelper"

# What the target's debhelper compat level decides (debhelper_compat_spec.rb
# checks it in rendered debian/ folders).
RSpec.describe Relspec::Debian::Debhelper do
  it "declares the level in Build-Depends from 11 on, in debian/compat before" do
    expect(described_class.relation(10)).to eq("debhelper (>= 10)")
    expect(described_class.relation(11)).to eq("debhelper-compat (= 11)")
    expect([described_class.compat_file?(10), described_class.compat_file?(11)]).to eq([true, false])
  end

  it "adds the autoreconf add-on for autotools below compat 10 only" do
    expect(described_class.options("autotools", 9)).to eq(" --buildsystem=autoconf --with autoreconf")
    expect(described_class.autoreconf("autotools", 9)).to eq(["dh-autoreconf"])
    expect(described_class.options("autotools", 10)).to eq(" --buildsystem=autoconf")
    expect(described_class.autoreconf("cmake", 9)).to eq([])
    expect(described_class.options("ruby", 13)).to eq("")
  end

  it "says which build types compile code" do
    expect(%w[cmake orogen autotools ruby gem meta].select { |type| described_class.compiled?(type) })
      .to eq(%w[cmake orogen autotools])
  end
end
