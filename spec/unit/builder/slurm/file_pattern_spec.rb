# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/builder/slurm/file_pattern"

RSpec.describe Relspec::Builder::Slurm::FilePattern do
  it "doubles every percent sign, so that sbatch writes to the path as named" do
    expect(described_class.escape("/p/release-100%j/logs/a%%b.log")).to eq("/p/release-100%%j/logs/a%%%%b.log")
    expect(described_class.escape("/p/plain.log")).to eq("/p/plain.log")
  end

  it "refuses a backslash, which sbatch drops, naming the path" do
    expect { described_class.escape("/p/a\\b/x.log") }
      .to raise_error(Relspec::BuildError, "/p/a\\b/x.log: Slurm cannot write a job's log to a path holding a " \
                                           "backslash (sbatch drops it); build from a folder without one")
  end
end
