# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/gem_versions"

# A gem_source folder of .gem files (only their names are read). The
# compact index, with a real server, is spec/relspec/catalog/gem_versions_spec.rb's.
RSpec.describe Relspec::Catalog::GemVersions do
  around do |example|
    Dir.mktmpdir("relspec-gem-versions") do |dir|
      @dir = dir
      example.run
    end
  end

  it "lists a folder's releases of a gem, highest first, and knows no Ruby of theirs (the .gem says)" do
    %w[core-1.2.0.gem core-1.10.0.gem core-2.0.0.rc1.gem core-1.1.0-java.gem core_ext-3.0.0.gem].each do |file|
      File.write(File.join(@dir, file), "")
    end
    versions = described_class.new(@dir, base_dir: "/")
    expect(versions.of("core").map(&:to_s)).to eq(%w[1.10.0 1.2.0])
    expect(versions.required_ruby("core", "1.10.0")).to be_nil
    expect(versions).to be_folder
  end
end
