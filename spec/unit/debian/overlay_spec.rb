# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/overlay"

# An overlay in a temporary project folder.
RSpec.describe Relspec::Debian::Overlay, :tmpdir do
  def write(relative, content)
    path = File.join(@dir.b, "overlays", "base", "cmake", relative.b)
    FileUtils.mkdir_p(File.dirname(path))
    File.binwrite(path, content)
  end

  let(:overlay) { described_class.for(@dir, "base/cmake") }

  it "reads files with placeholders replaced, and patches with a DEP-3 header" do
    write("files/README", "for @RELSPEC_RELEASE@\n")
    write("patches/01-fix.patch", "--- a/x\n+++ b/x\n")
    expect(overlay.files("@RELSPEC_RELEASE@" => "demo")).to eq("README" => "for demo\n")
    expect(overlay.patches("base/cmake").map(&:first)).to eq(["01-fix.patch"])
  end

  it "refuses a file name that is not UTF-8, naming it with the byte escaped" do
    write("debian/caf\xE9", "x")
    expect { overlay.debian_files({}) }.to raise_error(Relspec::InvalidInput) { |error|
      expect(error.diagnostics.join).to include("debian/caf\\xE9: error[overlay]: the file name is not UTF-8; rename it")
    }
  end
end
