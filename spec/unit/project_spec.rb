# frozen_string_literal: true

require "relspec/project"

# The folders of a release project, as relspec prints them: in memory (the
# one file-system question, the current folder, is Dir.pwd's).
RSpec.describe Relspec::Project do
  it "writes paths of the current folder's project without ./" do
    project = described_class.new(".")
    expect(project.specs_dir).to eq("specs")
    expect(project.lock_path("demo")).to eq("releases/demo/lock.yml")
    expect(project.osdeps_dir("demo")).to eq("releases/demo/osdeps")
    expect(project.release_index).to eq("releases/releases.yml")
  end

  it "keeps other roots as given" do
    expect(described_class.new("/srv/rock").lock_path("demo")).to eq("/srv/rock/releases/demo/lock.yml")
    expect(described_class.new("sub/dir").release_index).to eq("sub/dir/releases/releases.yml")
    expect(described_class.new("./sub").osdeps_dir("r")).to eq("sub/releases/r/osdeps")
  end

  it "is the folder above a spec's folder" do
    expect(described_class.of_spec("specs/demo.yml").root).to eq(".")
    expect(described_class.of_spec("/srv/rock/specs/demo.yml").lock_path("demo")).to eq("/srv/rock/releases/demo/lock.yml")
  end
end
