# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/file_lock"

# The one flock (target lock, repository lock): a second holder is told
# and either refused or made to wait; shared holders sit side by side.
RSpec.describe Relspec::FileLock do
  def hold(dir, **options, &block)
    described_class.hold(dir, "x.lock", busy: options.delete(:busy) || ->(_) { raise "busy" }, **options, &block)
  end

  it "makes the folder, and a second exclusive holder is refused while the first holds it" do
    Dir.mktmpdir do |tmp|
      dir = File.join(tmp, "a", "b")
      inner = hold(dir) { expect { hold(dir) { :inner } }.to raise_error(RuntimeError, "busy") }
      expect(inner).to be(true)
      expect(File.file?(File.join(dir, "x.lock"))).to be(true)
      expect(hold(dir) { :free }).to eq(:free)
    end
  end

  it "lets shared holders in beside each other, not an exclusive one" do
    Dir.mktmpdir do |dir|
      both = hold(dir, shared: true) { hold(dir, shared: true) { :both } }
      expect(both).to eq(:both)
      hold(dir, shared: true) { expect { hold(dir) { :no } }.to raise_error(RuntimeError, "busy") }
    end
  end

  it "waits when busy returns, and gets the lock once the holder lets go" do
    Dir.mktmpdir do |dir|
      told = Queue.new
      released = Queue.new
      holder = Thread.new do
        hold(dir) do
          told << :held
          released.pop
        end
      end
      told.pop
      waiter = Thread.new { hold(dir, busy: ->(file) { told << file.path }) { :got } }
      expect(told.pop).to eq(File.join(dir, "x.lock"))
      expect(waiter.alive?).to be(true)
      released << :go
      expect(waiter.value).to eq(:got)
      holder.join
    end
  end

  it "says which lock file cannot be made" do
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "file"), "")
      expect { hold(File.join(dir, "file", "sub")) { nil } }
        .to raise_error(described_class::Unavailable) { |e| expect([e.path, e.message]).to eq([File.join(dir, "file", "sub"), described_class::NOT_A_FOLDER]) }
    end
  end
end
