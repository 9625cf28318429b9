# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/package"
require "relspec/catalog/uncommitted_changes"

# What is asked of git (one `git status` per checkout) runs in
# spec/relspec/plan/uncommitted_changes_spec.rb on a real workspace; the
# unit layer starts no child, which is what is checked here: packages that
# are no git checkout are not asked about.
RSpec.describe Relspec::Catalog::UncommittedChanges do
  def package(name, type:, checked_out: true)
    Relspec::Catalog::Package.new(
      name: name, package_set: "set", build_type: "cmake", commit_time: "2020-06-01T00:00:00Z", source_dir: "src/#{name}",
      checked_out: checked_out, vcs: Relspec::Catalog::Vcs.new(type: type, url: "https://example.org/#{name}", commit: "c" * 40)
    )
  end

  it "asks nothing of packages that are no git checkout, nor of folders without .git" do
    Dir.mktmpdir do |root|
      FileUtils.mkdir_p(File.join(root, "src", "plain"))
      packages = [package("tarball", type: "archive"), package("absent", type: "git", checked_out: false),
                  package("plain", type: "git")]
      expect(described_class.read(root, packages)).to eq({})
    end
  end
end
