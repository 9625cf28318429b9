# frozen_string_literal: true

require "spec_helper"
require "relspec/reprepro/runner"
require "relspec/reprepro/config"
require "relspec/target"

# The one reprepro runner of publish and mirror, on a real repository of
# real .debs (reprepro is a child process: not in the unit layer).
RSpec.describe Relspec::Reprepro::Runner do
  around do |example|
    Dir.mktmpdir do |dir|
      @dir = dir
      source = AptRepositoryBuilder.new(File.join(dir, "source"), codenames: %w[bookworm], architectures: %w[amd64])
      source.add("rock-x", "1.0-1", codename: "bookworm", arch: "amd64")
      @deb = Dir[File.join(dir, "source", ".debs", "*.deb")].first
      @repo = File.join(dir, "repo")
      Relspec::Reprepro::Config.new(label: "t", description: "t %<codename>s", targets: [Relspec::Target.parse("bookworm/amd64")],
                                    source: false).write(File.join(@repo, "conf"))
      example.run
    end
  end

  def packages
    path = File.join(@repo, "dists", "bookworm", "main", "binary-amd64", "Packages")
    File.read(path).scan(/^Package: (.*)$/).flatten
  end

  it "includes, lists the pool, removes and exports" do
    runner = described_class.new(@repo)
    runner.includedeb("bookworm", [@deb], arch: "amd64")
    expect(packages).to eq(["rock-x"])
    expect(runner.pool_files).to eq(["pool/main/r/rock-x/rock-x_1.0-1_amd64.deb"])
    expect(runner.packages("bookworm")).to eq([%w[rock-x 1.0-1 amd64]])
    runner.remove("bookworm", ["rock-x"], arch: "amd64")
    runner.export
    runner.clearvanished
    expect(packages).to eq([])
  end

  it "raises the caller's error kind naming the command, its status and its output" do
    expect { described_class.new(@repo, error: Relspec::PublishError).includedeb("nosuch", [@deb]) }
      .to raise_error(Relspec::PublishError, /\Areprepro includedeb failed \(exit status \d+\) in #{Regexp.escape(@repo)}:\n.*nosuch/m)
    expect { described_class.new(@repo).remove("nosuch", ["x"], arch: "amd64") }
      .to raise_error(Relspec::ToolError, /\Areprepro remove failed/)
  end
end
