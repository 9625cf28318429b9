# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/cli/main"

RSpec.describe Relspec::CLI::Help do
  it "is the long help of the command of its name, each text used once" do
    commands = Relspec::CLI::Main.commands
    described_class.constants.each do |name|
      command = commands.fetch(name.to_s.downcase)
      expect(command.long_description).to eq(described_class.const_get(name)), name.to_s
    end
    used = commands.values.map(&:long_description).compact
    expect(used.size).to eq(used.uniq.size)
    expect(used.size).to eq(described_class.constants.size)
  end

  it "tells in publish's help that the debug-symbol packages are published only when asked" do
    expect(described_class::PUBLISH.tr("\n", " ")).to include("the -dbgsym .debs only with repository.debug_symbols: true")
  end
end
