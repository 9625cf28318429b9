# frozen_string_literal: true

require "spec_helper"
require "json"
require "relspec/availability/launchpad_page"

# The shape of a Launchpad collection page, checked at every level before
# anything reads it (issue 24): a wrong type is a failure naming the URL and
# the field, never a TypeError.
RSpec.describe Relspec::Availability::LaunchpadPage do
  failure = Class.new(Relspec::Error)
  url = "http://127.0.0.1:1/1.0/ubuntu/+archive/primary?ws.op=getPublishedBinaries"

  def page(body, url, failure)
    described_class.parse(body.is_a?(String) ? body : JSON.generate(body), url, failure: failure)
  end

  it "reads the entries and the link to the next page" do
    read = page({ "entries" => [{ "binary_package_name" => "cmake" }], "next_collection_link" => "https://x/2" }, url, failure)
    expect([read.entries.map { |e| e["binary_package_name"] }, read.next_link]).to eq([["cmake"], "https://x/2"])
    expect(page({ "entries" => [] }, url, failure).next_link).to be_nil
  end

  {
    "a list at the top" => [[], "the answer is not a collection"],
    "no entries" => [{ "total_size" => 0 }, "the answer is not a collection"],
    "entries as a number" => [{ "entries" => 7 }, "entries is a number, not a list"],
    "entries as an object" => [{ "entries" => { "a" => 1 } }, "entries is an object, not a list"],
    "entries as null" => [{ "entries" => nil }, "entries is null, not a list"],
    "an entry as text" => [{ "entries" => ["cmake"] }, "entries[0] is text, not an object"],
    "a name as a number" => [{ "entries" => [{ "binary_package_name" => "a" }, { "binary_package_name" => 3 }] },
                             "entries[1].binary_package_name is a number, not text"],
    "a name missing" => [{ "entries" => [{}] }, "entries[0].binary_package_name is null, not text"],
    "a link as a list" => [{ "entries" => [], "next_collection_link" => [] }, "next_collection_link is a list, not an http(s) URL"],
    "a link to a file" => [{ "entries" => [], "next_collection_link" => "file:///etc/passwd" },
                           'next_collection_link is "file:///etc/passwd", not an http(s) URL'],
    "a truncated answer" => ['{"entries": [{"binary_package_na', "the answer is not JSON"],
    "an empty answer" => ["", "the answer is not JSON"]
  }.each do |what, (body, message)|
    it "refuses #{what}, naming the URL and the field" do
      expect { page(body, url, failure) }.to raise_error(failure) { |error| expect(error.message).to start_with("Launchpad: #{url}: #{message}") }
    end
  end
end
