# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/apt/opening"
require "relspec/release_specs/values/repository_entry"
require "relspec/release_specs/values/archive"

RSpec.describe Relspec::Apt::Opening do
  let(:entry) { Relspec::ReleaseSpec::RepositoryEntry.new(path: "/srv/r", url: "http://127.0.0.1:1/r", trusted: true) }

  it "opens an entry at the location it is given" do
    repository = described_class.repository(entry, "http://127.0.0.1:1/r", fetcher_options: { timeout: 3 })
    expect(repository).to be_a(Relspec::Apt::Repository)
    expect(repository.url).to eq("http://127.0.0.1:1/r")
  end

  it "reads a `host: true` archive from this machine's apt lists, any other from its repository" do
    expect(described_class.archive(Relspec::ReleaseSpec::Archive.from({ "host" => true }), "/specs"))
      .to be_a(Relspec::Apt::HostLists)
    archive = Relspec::ReleaseSpec::Archive.from({ "url" => "http://127.0.0.1:1/debian", "trusted" => true })
    expect(described_class.archive(archive, "/specs").url).to eq("http://127.0.0.1:1/debian")
  end
end
