# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/location"
require "relspec/diagnostic"

RSpec.describe Relspec::Diagnostic do
  it "prints location, severity, rule, message and hint" do
    diagnostic = described_class.error("rule", "it broke", location: Relspec::Location.at("a.yml", 3, 5), hint: "fix it")
    expect(diagnostic.to_s).to eq("a.yml:3:5: error[rule]: it broke\n  hint: fix it")
  end

  # Issue 46, case 14: the file may be a path typed on the command line.
  it "escapes control characters in the file, the message and the hint, and keeps the message's own lines" do
    diagnostic = described_class.warning("rule", "two\nlines\e[31m", location: Relspec::Location.file_only("a\e[2J.yml"),
                                                                     hint: "\rhint")
    expect(diagnostic.to_s).to eq("a\\e[2J.yml: warning[rule]: two\nlines\\e[31m\n  hint: \\rhint")
  end
end
