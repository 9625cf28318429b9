# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/report/page"

RSpec.describe Relspec::Report::Page do
  def view(target, *packages)
    cells = packages.map { |name| Relspec::Report::Cell.new(package: name, decision: "build", version: target) }
    Relspec::Report::TargetView.new(target: target, cells: cells, totals: {}, build_seconds: 0, blockers: [],
                                    critical_path: [])
  end

  let(:page) { described_class.new(release: "r", targets: [view("bookworm/amd64", "b", "a"), view("jammy/arm64", "c", "a")]) }

  it "has a row per package of any target, sorted: the matrix's rows" do
    expect(page.packages).to eq(%w[a b c])
  end

  it "finds a target's cell of a package, nil where the target has none" do
    expect(page.targets.last.cell("a").version).to eq("jammy/arm64")
    expect(page.targets.last.cell("b")).to be_nil
  end
end
