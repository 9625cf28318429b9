# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/publish/inclusion_check"
require "relspec/target"

# What reprepro took, checked against what publish uploaded: reprepro
# skips a lower version than the one it holds and exits 0 (issue 44's grape
# pin). The listings are values here; spec/relspec/publish/publish_spec.rb
# has a real repository refuse a lower version.
RSpec.describe Relspec::Publish::InclusionCheck do
  let(:target) { Relspec::Target.parse("bookworm/amd64") }
  let(:upload) do
    Struct.new(:source, :version, :dsc, :debs, keyword_init: true)
          .new(source: "rock-r-ruby-grape", version: "3.0.1-1~bookworm", dsc: "/out/rock-r-ruby-grape_3.0.1-1~bookworm.dsc",
               debs: ["/out/rock-r-ruby-grape_3.0.1-1~bookworm_all.deb"])
  end

  def check(listing)
    described_class.new(target, listing).check([upload])
  end

  it "passes when the distribution lists the source and every .deb at their versions" do
    expect(check([%w[rock-r-ruby-grape 3.0.1-1~bookworm source], %w[rock-r-ruby-grape 3.0.1-1~bookworm amd64]])).to be_nil
  end

  it "names each file reprepro kept a higher version for, and what it kept" do
    listing = [%w[rock-r-ruby-grape 3.1.1-1~bookworm source], %w[rock-r-ruby-grape 3.1.1-1~bookworm amd64]]
    expect { check(listing) }.to raise_error(Relspec::PublishError) do |error|
      expect(error.message).to start_with("bookworm/amd64: reprepro did not take 2 file(s) of rock-r-ruby-grape")
      expect(error.message).to include("  rock-r-ruby-grape_3.0.1-1~bookworm.dsc: it keeps rock-r-ruby-grape 3.1.1-1~bookworm\n",
                                       "  rock-r-ruby-grape_3.0.1-1~bookworm_all.deb: it keeps rock-r-ruby-grape 3.1.1-1~bookworm\n",
                                       "nothing was published", "+really")
    end
  end

  it "looks at the target's architecture only, and compares versions without their epoch as file names carry them" do
    other_arch = [%w[rock-r-ruby-grape 3.0.1-1~bookworm source], %w[rock-r-ruby-grape 3.0.1-1~bookworm arm64]]
    expect { check(other_arch) }.to raise_error(Relspec::PublishError, /_all\.deb: it lists no rock-r-ruby-grape\n/)
    epoch = Struct.new(:source, :version, :dsc, :debs, keyword_init: true)
                  .new(source: "s", version: "1:2.0-1", dsc: "/o/s_2.0-1.dsc", debs: ["/o/s-bin_2.0-1_amd64.deb"])
    expect(described_class.new(target, [%w[s 1:2.0-1 source], %w[s-bin 1:2.0-1 amd64]]).check([epoch])).to be_nil
  end
end
