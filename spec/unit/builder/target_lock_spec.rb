# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/builder/target_lock"

# One build (or publish) of a target folder at a time, on Relspec::FileLock.
RSpec.describe Relspec::Builder::TargetLock do
  it "refuses a second build at once, naming what it wanted and the holder" do
    Dir.mktmpdir do |dir|
      described_class.hold(dir, "build") do
        expect { described_class.hold(dir, "publish", shared: true) { nil } }
          .to raise_error(described_class::Busy, /\Acannot publish #{Regexp.escape(dir)}: .* is using it; run again/)
      end
      expect(described_class.hold(dir, "build") { :built }).to eq(:built)
    end
  end

  it "lets publishes share it" do
    Dir.mktmpdir do |dir|
      expect(described_class.hold(dir, "publish", shared: true) { described_class.hold(dir, "publish", shared: true) { :both } })
        .to eq(:both)
    end
  end

  it "words a folder it cannot lock as a user error" do
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "file"), "")
      expect { described_class.hold(File.join(dir, "file"), "build") { nil } }
        .to raise_error(Relspec::Error, /\Acannot build .*file: cannot lock it \(.*\.relspec-target\.lock: File exists\)/)
    end
  end
end
