# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/target"
require "relspec/mirror/proof"

# The proofs run dose-debcheck and mmdebstrap (the mirror CI test and
# spec/hostile/mirror_input_spec.rb run them, and the install hook under
# sh); here, what needs no child process.
RSpec.describe Relspec::Mirror::Proof do
  it "skips the dynamic proof of an architecture this machine cannot run, saying how to run it" do
    check = described_class.new(nil).dynamic(Relspec::Target.parse("bookworm/arm64"), %w[rock-a], arch_runs: false)
    expect([check.name, check.status, check.problems]).to eq(["dynamic", "skipped", []])
    expect(check.detail).to include("cannot run arm64 programs", "qemu-user-static")
  end

  it "gives apt the release's names after --, from the environment, unglobbed" do
    hook = described_class::INSTALL_HOOK
    expect(hook).to start_with("set -f;").and end_with("install -- $#{described_class::PACKAGES_VARIABLE}")
    expect(hook.scan("apt-get").size).to eq(1)
  end
end
