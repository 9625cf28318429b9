# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan"
require "relspec/plan/report"

# The plan's text and markdown, fed a ReleasePlan in memory.
RSpec.describe Relspec::Plan::Report do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }

  def build(name, revision, cutoff: nil)
    Relspec::Plan::Decision.new(package: name, kind: :build, deb_name: "rock-r-#{name.tr('/', '-')}",
                                version: Relspec::Debian::PackageVersion.new("1.0", revision, "bookworm"),
                                cause: Relspec::Plan::Cause.missing, cutoff: cutoff).freeze
  end

  it "names each early cutoff candidate under its build, with the version it keeps and what decides" do
    cutoff = Relspec::Plan::CutoffCandidate.new(keeps: Relspec::Debian::PackageVersion.new("1.0", 1, "bookworm"),
                                                because: ["base/lib"])
    plan = Relspec::Plan::ReleasePlan.new(release: "r", targets: { target => { "base/lib" => build("base/lib", 2),
                                                                               "base/user" => build("base/user", 2, cutoff: cutoff) } },
                                          packages: {}, release_digests: {}, warnings: [], notes: [])
    report = described_class.new(plan, Struct.new(:ancestors).new({}))
    expect(report.text).to include("  base/lib   rock-r-base-lib 1.0-2\n    missing in all ancestors\n  base/user  ")
    expect(report.text).to include("  base/user  rock-r-base-user 1.0-2\n    missing in all ancestors\n    early cutoff candidate: " \
                                   "1.0-1~bookworm stays if the interface of base/lib does not change\n")
    expect(report.markdown).to include("- `base/user` (`rock-r-base-user`): missing in all ancestors; early cutoff candidate: " \
                                       "1.0-1~bookworm stays if the interface of base/lib does not change\n")
  end

  it "lists the published packages the early cutoff kept, with why" do
    kept = Relspec::Plan::Decision.new(package: "base/user", kind: :published, deb_name: "rock-r-base-user",
                                       version: Relspec::Debian::PackageVersion.new("1.0", 1, "bookworm"),
                                       cause: Relspec::Plan::Cause.missing, kept: "the interface of base/lib did not change").freeze
    plan = Relspec::Plan::ReleasePlan.new(release: "r", targets: { target => { "base/user" => kept } },
                                          packages: {}, release_digests: {}, warnings: [], notes: [])
    report = described_class.new(plan, Struct.new(:ancestors).new({}))
    expect(report.text).to include("\nkept by the early cutoff on bookworm/amd64:\n  base/user  rock-r-base-user " \
                                   "1.0-1~bookworm: the interface of base/lib did not change\n")
    expect(report.markdown).to include("**Kept by the early cutoff on bookworm/amd64**\n\n- `base/user`: rock-r-base-user " \
                                       "1.0-1~bookworm: the interface of base/lib did not change")
  end
end
