# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/gem_archive"
require_relative "../../support/in_process_gem"

# A .gem read from a gem_source folder, written in-process.
RSpec.describe Relspec::Catalog::GemArchive do
  around do |example|
    Dir.mktmpdir("relspec-gem-archive") do |dir|
      @dir = dir
      example.run
    end
  end

  def fetch(name, version)
    described_class.fetch(name, version, source: @dir, base_dir: "/", cache_dir: nil)
  end

  it "reads the gemspec: its runtime dependencies and the Ruby it needs (>= 0 when it says none)" do
    InProcessGem.write(@dir, "types", "1.9.1", dependencies: { "core" => "~> 1.0" }, ruby: ">= 3.2")
    InProcessGem.write(@dir, "core", "1.0.0")
    expect(fetch("types", "1.9.1").runtime_dependencies).to eq([["core", Gem::Requirement.new("~> 1.0")]])
    expect(fetch("types", "1.9.1").required_ruby).to eq(Gem::Requirement.new(">= 3.2"))
    expect(fetch("core", "1.0.0").required_ruby).to eq(Gem::Requirement.default)
  end

  it "refuses a .gem that holds another gem than its name says" do
    FileUtils.cp(InProcessGem.write(@dir, "core", "1.0.0"), File.join(@dir, "core-1.1.0.gem"))
    expect { fetch("core", "1.1.0") }.to raise_error(described_class::Problem, /core-1\.1\.0\.gem holds core 1\.0\.0, not core 1\.1\.0/)
  end
end
