# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/report/critical_path"

RSpec.describe Relspec::Report::CriticalPath do
  PathEntry = Struct.new(:source, :build_depends)

  def path(entries, durations)
    described_class.of(entries.map { |source, needs| PathEntry.new(source, needs) }, durations).map(&:to_h)
  end

  it "follows the build-dependencies whose times add up to the most" do
    entries = { "cmake" => [], "types" => ["cmake"], "logging" => ["cmake"], "driver" => %w[types logging],
                "apart" => [] }
    expect(path(entries, "cmake" => 2, "types" => 10, "logging" => 3, "driver" => 4, "apart" => 15))
      .to eq([{ "source" => "cmake", "duration" => 2 }, { "source" => "types", "duration" => 10 },
              { "source" => "driver", "duration" => 4 }])
  end

  it "breaks ties by name, counts builds without a time as zero, and is empty without times" do
    entries = { "b" => [], "a" => [], "c" => %w[b a] }
    expect(path(entries, "a" => 1, "b" => 1)).to eq([{ "source" => "a", "duration" => 1 }])
    expect(path(entries, "a" => 1, "b" => 1, "c" => 0.5)).to eq([{ "source" => "a", "duration" => 1 },
                                                                 { "source" => "c", "duration" => 0.5 }])
    expect(path(entries, {})).to eq([])
  end
end
