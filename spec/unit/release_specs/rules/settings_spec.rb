# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/settings"

RSpec.describe Relspec::ReleaseSpec::Rules::Settings do
  def check(text)
    findings(described_class.call(spec_file("release: child\n#{text}")))
  end

  it "accepts well-formed settings" do
    expect(check(<<~YAML)).to eq([])
      install_prefix: /opt/rock
      package_prefix: rock
      maintainer: Rock Packaging <rock-dev@example.org>
      gems: { rice: "4.0.2" }
      gem_source: https://rubygems.org
      select: [base/types, rock.core]
    YAML
  end

  it "refuses an install prefix that is not a plain absolute path" do
    expect(check("install_prefix: /opt/../etc\n").first).to start_with('error install-prefix@2: install_prefix "/opt/../etc"')
    expect(check("install_prefix: opt/rock\n").size).to eq(1)
  end

  it "refuses a package prefix that cannot start a Debian name, and a malformed maintainer" do
    expect(check("package_prefix: Rock\nmaintainer: rock-dev@example.org\n")).to eq([
      'error package-prefix@2: package prefix "Rock" cannot start a Debian package name',
      'error maintainer@3: maintainer "rock-dev@example.org" is not of the form "Name <address>"'
    ])
  end

  it "refuses gem names and versions relspec cannot package" do
    expect(check("gems:\n  \"-rice\": \"4.0\"\n  rake: \">= 13\"\n")).to eq([
      'error gem-name@3: "-rice" is not a gem name',
      'error gem-version@4: version ">= 13" of gem rake is not an exact version'
    ])
  end

  it "refuses a gem source URL of another scheme, and selections that are not package names" do
    expect(check("gem_source: ftp://gems.example.org\nselect: [base/types, \"not a name\"]\n")).to eq([
      'error repository-url@2: url "ftp://gems.example.org" is not an http(s) or file URL',
      'error package-name@3: "not a name" is not a package or metapackage name'
    ])
  end

  it "asks a distribution relspec does not know for its type and labels" do
    expect(check("distributions:\n  duke: { archive: { host: true } }\n")).to eq([
      'error missing-key@3: missing required key "labels" (duke is not a built-in distribution)',
      'error missing-key@3: missing required key "type" (duke is not a built-in distribution)'
    ])
  end

  it "refuses an archive that is both this machine's lists and a location" do
    expect(check("distributions:\n  bionic:\n    archive: { host: true, url: \"http://a/b\" }\n"))
      .to eq(["error archive-host@4: the archive of bionic sets host: true and url"])
  end
end
