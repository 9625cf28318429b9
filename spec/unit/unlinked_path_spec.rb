# frozen_string_literal: true

require_relative "unit_helper"
require "tmpdir"
require "fileutils"
require "relspec/unlinked_path"

RSpec.describe Relspec::UnlinkedPath do
  around do |example|
    Dir.mktmpdir("relspec-unlinked") do |dir|
      @base = File.join(dir, "base")
      @outside = File.join(dir, "outside")
      FileUtils.mkdir_p([File.join(@base, "logs"), @outside])
      example.run
    end
  end

  it "finds no link on a path of plain folders, existing or not" do
    expect(described_class.first_link(@base, "logs/a/b.log")).to be_nil
    expect(described_class.check(@base, "logs/a/b.log", why: "x")).to eq(File.join(@base, "logs", "a", "b.log"))
  end

  it "names the first link on the way, where it points and why, with the error asked for" do
    File.symlink(@outside, File.join(@base, "report"))
    expect(described_class.first_link(@base, "report/logs/a.log")).to eq(File.join(@base, "report"))
    expect { described_class.check(@base, "report/logs/a.log", why: "never through a link", error: Relspec::PublishError) }
      .to raise_error(Relspec::PublishError, "#{@base}/report is a symbolic link (to #{@outside}): never through a link")
  end

  it "escapes a link's target that would drive the terminal" do
    File.symlink("\e[31mred", File.join(@base, "logs", "a.log"))
    expect { described_class.check(@base, "logs/a.log", why: "no") }
      .to raise_error(Relspec::Error, "#{@base}/logs/a.log is a symbolic link (to \\e[31mred): no")
  end
end
