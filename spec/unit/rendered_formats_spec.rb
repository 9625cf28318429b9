# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/rendered_formats"

RSpec.describe Relspec::RenderedFormats do
  let(:report) do
    Class.new do
      include Relspec::RenderedFormats

      def text = "text\n"
      def markdown = "# md\n"
      def to_h = { "b" => [1], "a" => "x" }
    end.new
  end

  it "renders text by default, markdown, and the same JSON of to_h for every report" do
    expect(report.render("text")).to eq("text\n")
    expect(report.render(nil)).to eq("text\n")
    expect(report.render("markdown")).to eq("# md\n")
    expect(report.render("json")).to eq("{\n  \"b\": [\n    1\n  ],\n  \"a\": \"x\"\n}\n")
  end
end
