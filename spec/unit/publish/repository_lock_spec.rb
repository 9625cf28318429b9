# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/publish/repository_lock"

# One publisher per repository, on Relspec::FileLock: the second waits.
RSpec.describe Relspec::Publish::RepositoryLock do
  it "makes a second publisher wait, telling it once, until the first is done" do
    Dir.mktmpdir do |dir|
      held = Queue.new
      release = Queue.new
      told = Queue.new
      first = Thread.new do
        described_class.hold(dir) do
          held << true
          release.pop
        end
      end
      held.pop
      second = Thread.new { described_class.hold(dir, waiting: ->(who) { told << who }) { :published } }
      expect(told.pop).to eq("another relspec publish")
      release << true
      expect(second.value).to eq(:published)
      first.join
    end
  end

  it "is a PublishError naming the repository it cannot lock" do
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "repo"), "")
      expect { described_class.hold(File.join(dir, "repo")) { nil } }
        .to raise_error(Relspec::PublishError, /\Acannot lock the repository .*repo: /)
    end
  end
end
