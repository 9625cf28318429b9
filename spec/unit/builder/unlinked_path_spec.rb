# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "fileutils"
require "relspec/builder/unlinked_path"

RSpec.describe Relspec::Builder::UnlinkedPath do
  around do |example|
    Dir.mktmpdir("relspec-unlinked") do |dir|
      @base = File.join(dir, "target")
      @outside = File.join(dir, "outside")
      FileUtils.mkdir_p([File.join(@base, "logs"), @outside])
      example.run
    end
  end

  it "answers the joined path when no part of it is a link, existing or not" do
    expect(described_class.check(@base, "logs/a.log")).to eq(File.join(@base, "logs", "a.log"))
    expect(described_class.check(@base, "results/a")).to eq(File.join(@base, "results", "a"))
  end

  it "refuses a file that is a link, naming it and where it points" do
    File.symlink(File.join(@outside, "f"), File.join(@base, "logs", "a.log"))
    expect { described_class.check(@base, "logs/a.log") }
      .to raise_error(Relspec::BuildError, "#{@base}/logs/a.log is a symbolic link (to #{@outside}/f): a build writes " \
                                           "only inside #{@base} and never through a link; remove the link and build again")
  end

  it "refuses a folder on the way that is a link, even to a folder inside" do
    File.symlink("logs", File.join(@base, "results"))
    expect { described_class.check(@base, "results/a") }.to raise_error(Relspec::BuildError, %r{#{@base}/results is a symbolic link \(to logs\)})
  end
end
