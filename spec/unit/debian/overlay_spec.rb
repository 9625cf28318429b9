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

  describe "per distribution (@<codename>/) and per architecture (@<arch>/)" do
    let(:trixie) { described_class.for(@dir, "base/cmake", arch: "amd64", codename: "trixie") }
    let(:bookworm) { described_class.for(@dir, "base/cmake", arch: "amd64", codename: "bookworm") }

    before do
      write("patches/01-common.patch", "common\n")
      write("@trixie/patches/02-gcc14.patch", "trixie\n")
      write("debian/NOTE", "common\n")
      write("@trixie/debian/NOTE", "trixie\n")
      write("@trixie/debian/ONLY", "trixie only\n")
      write("@amd64/debian/ONLY", "amd64\n")
    end

    it "adds the codename's patches and debian/ files over the common ones, the architecture's over those" do
      expect(trixie.patches("base/cmake").map(&:first)).to eq(%w[01-common.patch 02-gcc14.patch])
      expect(trixie.debian_files({})).to eq("NOTE" => "trixie\n", "ONLY" => "amd64\n")
      expect(bookworm.patches("base/cmake").map(&:first)).to eq(%w[01-common.patch])
      expect(bookworm.debian_files({})).to eq("NOTE" => "common\n", "ONLY" => "amd64\n")
    end

    it "changes the signature of that codename's targets only" do
      plain = described_class.for(@dir, "base/cmake", arch: "amd64")
      expect(bookworm.signature).to eq(plain.signature)
      expect(trixie.signature).not_to eq(bookworm.signature)
    end

    it "refuses files/ in a codename's layer: the orig tarball is every target's" do
      write("@trixie/files/x", "x")
      expect { trixie }.to raise_error(Relspec::InvalidInput) { |error|
        expect(error.diagnostics.join).to include("@trixie/files: error[overlay]: files/ cannot be per distribution " \
                                                  "(use a patch in @trixie/patches/)")
      }
      expect(bookworm.patches("base/cmake").size).to eq(1)
    end

    it "names the codename's patch file when its name cannot be listed in the series" do
      write("@trixie/patches/bad name.patch", "x")
      expect { trixie.patches("base/cmake") }.to raise_error(Relspec::InvalidInput) { |error|
        expect(error.diagnostics.join).to include("overlays/base/cmake/@trixie/patches/bad name.patch")
      }
    end
  end
end
