# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/publish/repository_lock"

# One publisher per repository; a second one waits and is told for whom
# (issue 46, case 16). The other publisher is this process's own second
# open file of the lock (flocks of two open files exclude each other).
RSpec.describe Relspec::Publish::RepositoryLock do
  around do |example|
    Dir.mktmpdir("repository-lock") do |dir|
      @repository = File.join(dir, "repo")
      example.run
    end
  end

  it "waits for the publisher holding the lock, naming its pid and since when, then holds it" do
    FileUtils.mkdir_p(@repository)
    told = Queue.new
    waiter = File.open(File.join(@repository, described_class::FILE_NAME), File::RDWR | File::CREAT) do |other|
      other.flock(File::LOCK_EX)
      waiter = Thread.new { described_class.hold(@repository, waiting: ->(who) { told << who }) { :held } }
      expect(told.pop).to match(/\A.+ \(pid #{Process.pid}, since \d{4}-\d\d-\d\d \d\d:\d\d:\d\d UTC\)\z/)
      waiter
    end
    expect(waiter.value).to eq(:held)
  end

  it "refuses a repository path that is a file, or below one, saying so (not mkdir's 'File exists')" do
    File.write(@repository, "")
    [@repository, File.join(@repository, "sub")].each do |path|
      expect { described_class.hold(path) { nil } }
        .to raise_error(Relspec::PublishError, "cannot lock the repository #{path}: it, or a folder above it, is a file, " \
                                               "not a folder")
    end
  end
end
