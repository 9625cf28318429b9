# frozen_string_literal: true

require "spec_helper"
require "relspec/catalog/autoproj_loader"
require_relative "../../support/rock_workspace_context"

# relspec loads a workspace once per target distribution; what autoproj says
# while loading (here: the Rock package set overrides autoproj's own cmake
# osdep, as the real rock.core does) must reach the user once, on stderr,
# as plain text, never on stdout.
RSpec.describe Relspec::Catalog::AutoprojMessages do
  it "keeps a warning's indented lines with it and gives each whole warning once, in order" do
    messages = described_class.new
    2.times do
      ["  WARN: osdeps definition for cmake overridden:", "  WARN:   resp. apt-dpkg: cmake", "  WARN: other",
       "  WARN: osdeps definition for cmake overridden:", "  WARN:   resp. apt-dpkg: cmake3"].each { |line| messages.add(line) }
    end
    expect(messages.to_s).to eq(<<~TEXT)
      \  WARN: osdeps definition for cmake overridden:
      \  WARN:   resp. apt-dpkg: cmake
      \  WARN: other
      \  WARN: osdeps definition for cmake overridden:
      \  WARN:   resp. apt-dpkg: cmake3
    TEXT
  end

  context "through the CLI, on a workspace of real Rock package sets" do
    include_context "a real Rock workspace"

    it "says autoproj's warnings once for all targets, on stderr, without terminal styles" do
      FileUtils.mkdir_p(File.join(@dir, "specs"))
      File.write(File.join(@dir, "specs", "r.yml"),
                 "release: r\nworkspace: ../ws/workspace\ntargets: { bookworm: [amd64], bullseye: [amd64], focal: [amd64] }\n")
      run = relspec("catalog", "show", "specs/r.yml", chdir: @dir)
      expect(run.exit_code).to eq(0), run.stderr
      expect(run.stderr.scan("WARN: osdeps definition for cmake").size).to eq(1), run.stderr
      expect(run.stderr).to include("  WARN:   resp. apt-dpkg: cmake\n  WARN:         osdep: build-essential\n  WARN:   and   apt-dpkg: cmake\n")
      expect(run.stderr).not_to include("\e[")
      expect(run.stdout).not_to include("WARN")
      expect(run.stdout).to include("bookworm: 4 packages")
    end
  end
end
