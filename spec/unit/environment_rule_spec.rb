# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/environment_rule"

# What an env.yml may change, for compile's env.yml and the package set
# (Osdeps::Trust.environment is this rule; trust_spec covers its cases).
RSpec.describe Relspec::EnvironmentRule do
  it "takes a search path below the release's prefix and refuses one outside it" do
    entry = { type: :add_path, values: ["/srv/rock/r/p/lib"] }
    expect(described_class.problem("LD_LIBRARY_PATH", entry, prefix: "/srv/rock")).to be_nil
    expect(described_class.problem("LD_LIBRARY_PATH", entry))
      .to eq('LD_LIBRARY_PATH: "/srv/rock/r/p/lib" is not a path below /opt/rock')
  end

  it "refuses a variable that would run code in the workspace" do
    expect(described_class.problem("LD_PRELOAD", { type: :set, values: ["/opt/rock/x.so"] }))
      .to eq('"LD_PRELOAD" is not a variable the package set lets a package change')
  end

  it "is what Osdeps::Trust checks" do
    require "relspec/osdeps/trust"
    expect(Relspec::Osdeps::Trust::PREFIX).to eq(described_class::PREFIX)
    expect(Relspec::Osdeps::Trust.environment("RUBYOPT", { type: :set, values: ["-rx"] }))
      .to eq(described_class.problem("RUBYOPT", { type: :set, values: ["-rx"] }))
  end
end
