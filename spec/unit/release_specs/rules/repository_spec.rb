# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/repository"

RSpec.describe Relspec::ReleaseSpec::Rules::Repository do
  def check(text)
    findings(described_class.call(spec_file("release: child\nrepository:\n#{text}")))
  end

  it "accepts a path, an http(s) or file url, with a keyring or trusted" do
    expect(check("  path: build/repo\n  trusted: true\n")).to eq([])
    expect(check("  url: https://example.org/rock\n  keyring: keys/rock.gpg\n")).to eq([])
    expect(check("  url: file:///srv/rock\n")).to eq([])
  end

  it "refuses a repository that says neither where it is written nor read" do
    expect(check("  keyring: k.gpg\n")).to eq(["error repository-location@3: the repository has neither path nor url"])
  end

  it "refuses other URL schemes and unparsable URLs" do
    expect(check("  url: ftp://example.org/rock\n"))
      .to eq(['error repository-url@3: url "ftp://example.org/rock" is not an http(s) or file URL'])
    expect(check("  url: \"http://exa mple.org\"\n")).to eq(['error repository-url@3: url "http://exa mple.org" is not a valid URL'])
  end

  it "refuses a keyring together with trusted: true, at trusted" do
    expect(check("  path: repo\n  keyring: k.gpg\n  trusted: true\n"))
      .to eq(["error repository-trust@5: the repository sets both keyring and trusted: true"])
  end
end
