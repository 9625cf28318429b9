# frozen_string_literal: true

require_relative "unit_helper"
require "tmpdir"
require "fileutils"
require "relspec/report"

RSpec.describe Relspec::Report do
  let(:page) { Relspec::Report::Page.new(release: "child", ancestor: nil, targets: []) }

  it "writes the page with a copy of each log it links to, and removes the logs it no longer links to" do
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "build.log"), "error: x\n")
      out = File.join(dir, "report")
      FileUtils.mkdir_p(File.join(out, "logs", "bookworm-amd64"))
      File.write(File.join(out, "logs", "bookworm-amd64", "old.log"), "old")
      path = described_class.write(page, { "logs/bookworm-amd64/new.log" => File.join(dir, "build.log") }, out, "html")
      expect(path).to eq(File.join(out, "index.html"))
      expect(File.read(path)).to include("<h1>Release child</h1>")
      expect(Dir.glob("**/*", base: out).sort).to eq(%w[index.html logs logs/bookworm-amd64 logs/bookworm-amd64/new.log])
      expect(File.read(File.join(out, "logs", "bookworm-amd64", "new.log"))).to eq("error: x\n")
      expect(File.read(described_class.write(page, {}, out, "json"))).to start_with("{\n  \"relspec_report\": 1,")
    end
  end

  it "refuses a format it does not know before reading anything" do
    expect { described_class.run("nowhere.yml", out: "build", format: "pdf") }
      .to raise_error(Relspec::InvalidOption, 'unknown format "pdf" (known: html, json)')
  end
end
