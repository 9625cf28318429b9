# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/snapshot_shape"

RSpec.describe Relspec::Catalog::SnapshotShape do
  def package(patches)
    { "packages" => { "x" => { "build_type" => "cmake", "patches" => patches } } }
  end

  it "accepts import patches with a path, a level from 0 and their text" do
    expect(described_class.valid?(package([{ "path" => "p", "level" => 0, "content" => "t" }]))).to be(true)
  end

  it "refuses import patches without text, with a negative level, or not in a list" do
    [[{ "path" => "p", "level" => 0 }], [{ "path" => "p", "level" => -1, "content" => "t" }], "p"].each do |patches|
      problems = described_class.problems(package(patches), nil)
      expect(problems.map(&:message).join).to include("packages.x.patches"), patches.inspect
    end
  end
end
