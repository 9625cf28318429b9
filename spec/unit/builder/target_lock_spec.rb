# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/builder/target_lock"

# One build of a target folder at a time, on Relspec::FileLock; the second
# is refused naming the holder and since when (issue 46, case 16). The
# holder here is this process through a first hold (flocks of two open
# files exclude each other).
RSpec.describe Relspec::Builder::TargetLock do
  it "refuses a second holder at once, naming the first one's pid and start, and lets publishers share" do
    Dir.mktmpdir("target-lock") do |dir|
      described_class.hold(dir, "build") do
        expect { described_class.hold(dir, "publish", shared: true) { nil } }
          .to raise_error(described_class::Busy, /\Acannot publish #{Regexp.escape(dir)}: .+ \(pid #{Process.pid}, since \d{4}-\d\d-\d\d \d\d:\d\d:\d\d UTC\) is using it; run again when it has finished\z/)
      end
      shared = described_class.hold(dir, "publish", shared: true) { described_class.hold(dir, "publish", shared: true) { :both } }
      expect(shared).to eq(:both)
      expect(described_class.hold(dir, "build") { :built }).to eq(:built)
    end
  end

  it "words a folder it cannot lock as a user error" do
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "file"), "")
      expect { described_class.hold(File.join(dir, "file"), "build") { nil } }
        .to raise_error(Relspec::Error, /\Acannot build .*file: cannot lock it \(.*file: it, or a folder above it, is a file, not a folder\)\z/)
    end
  end
end
