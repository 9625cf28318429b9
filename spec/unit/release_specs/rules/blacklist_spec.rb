# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/blacklist"

RSpec.describe Relspec::ReleaseSpec::Rules::Blacklist do
  def check(text)
    findings(described_class.call(spec_file("release: child\nblacklist:\n#{text}")))
  end

  it "accepts patterns with reasons" do
    expect(check("  - { match: base/types, reason: new API }\n  - { match: \"simulation/*\", reason: not needed }\n")).to eq([])
  end

  it "warns about an entry without a reason, and shows how to give one" do
    diagnostics = described_class.call(spec_file("release: child\nblacklist:\n  - base/types\n"))
    expect(findings(diagnostics)).to eq(['warning blacklist-reason@3: blacklist entry "base/types" gives no reason'])
    expect(diagnostics.first.hint).to eq('write { match: "base/types", reason: "why it is rebuilt here" }')
  end

  it "warns about an entry listed twice, naming the first line" do
    diagnostics = described_class.call(
      spec_file("release: child\nblacklist:\n  - { match: base/types, reason: a }\n  - { match: base/types, reason: b }\n")
    )
    expect(findings(diagnostics)).to eq(['warning duplicate-blacklist@4: blacklist entry "base/types" is listed twice'])
    expect(diagnostics.first.hint).to eq("it is already listed at line 3")
  end

  it "refuses a pattern that cannot match a package name" do
    expect(check("  - { match: \"base//types\", reason: a }\n").map { |line| line[/\A\w+ [\w-]+@\d+/] })
      .to eq(["error #{Relspec::ReleaseSpec::PackagePattern.parse('base//types').rule}@3"])
  end
end
