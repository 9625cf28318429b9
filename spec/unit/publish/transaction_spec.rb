# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/publish/transaction"

# The switch and the recoveries of Publish::Transaction on plain folders
# (no reprepro: the block stands for its work on the copy).
RSpec.describe Relspec::Publish::Transaction, :tmpdir do
  let(:transaction) { described_class.new(@dir) }
  let(:work) { File.join(@dir, described_class::WORK) }

  before do
    { "conf/distributions" => "old conf\n", "db/packages.db" => "old db\n", "db/lockfile" => "",
      "dists/bookworm/Release" => "old release\n" }.each do |path, text|
      FileUtils.mkdir_p(File.dirname(File.join(@dir, path)))
      File.write(File.join(@dir, path), text)
    end
  end

  def live
    %w[conf db dists].flat_map { |name| Dir.glob("#{name}/**/*", base: @dir) }.sort.to_h do |path|
      file = File.join(@dir, path)
      [path, File.file?(file) ? File.read(file) : :dir]
    end
  end

  # A transaction whose block changed the copy of db/ and dists/; with
  # +fail+ the block raises instead, after its changes.
  def publish(fail: false)
    transaction.run do |dirs|
      expect(File.exist?(File.join(dirs[:db], "lockfile"))).to be(false) # reprepro's lock is not copied
      File.write(File.join(dirs[:db], "packages.db"), "new db\n")
      File.write(File.join(dirs[:dists], "bookworm", "Release"), "new release\n")
      raise Relspec::PublishError, "refused" if fail

      :done
    end
  end

  it "switches to the new state when the block ends, and removes its work folder" do
    expect(publish).to eq(:done)
    expect(live).to include("db/packages.db" => "new db\n", "dists/bookworm/Release" => "new release\n",
                            "conf/distributions" => "old conf\n")
    expect(live).not_to include("db/lockfile") # the new database has none of the old one's lock
    expect(File.exist?(work)).to be(false)
  end

  it "leaves the live folders as they were and removes its copy when the block fails" do
    before = live
    expect { publish(fail: true) }.to raise_error(Relspec::PublishError, "refused")
    expect(live).to eq(before)
    expect(File.exist?(work)).to be(false)
  end

  it "discards the work of a publish killed before it was ready, and answers :discarded" do
    before = live
    FileUtils.mkdir_p(File.join(work, "db"))
    File.write(File.join(work, "db", "packages.db"), "half a copy")
    expect(transaction.recover).to eq(:discarded)
    expect(live).to eq(before)
    expect(File.exist?(work)).to be(false)
  end

  it "finishes a switch killed half-way when the live and new states are those it recorded" do
    allow(File).to receive(:rename).and_call_original
    renames = 0
    allow(File).to receive(:rename).with(anything, File.join(@dir, "db")) do
      renames += 1
      raise Interrupt, "killed" # the second rename of db/ never happens
    end
    expect { publish }.to raise_error(Interrupt)
    expect(renames).to eq(1)
    expect(File.exist?(File.join(@dir, "db"))).to be(false)
    allow(File).to receive(:rename).and_call_original # the next run is not killed

    transaction.undo_half_rename
    expect(File.read(File.join(@dir, "db", "packages.db"))).to eq("old db\n")
    expect(transaction.recover).to eq(:finished)
    expect(live).to include("db/packages.db" => "new db\n", "dists/bookworm/Release" => "new release\n")
    expect(File.exist?(work)).to be(false)
  end

  it "puts back what a switch had replaced when the live database changed since (a hand include): :abandoned" do
    allow(File).to receive(:rename).and_call_original
    allow(File).to receive(:rename).with(File.join(work, "db"), anything).and_raise(Interrupt)
    expect { publish }.to raise_error(Interrupt)
    allow(File).to receive(:rename).and_call_original # the next run is not killed
    expect(File.read(File.join(@dir, "dists", "bookworm", "Release"))).to eq("new release\n")
    transaction.undo_half_rename # as publish does before it locks db/
    File.write(File.join(@dir, "db", "packages.db"), "old db and a package included by hand\n")

    expect(transaction.recover).to eq(:abandoned)
    expect(live).to include("db/packages.db" => "old db and a package included by hand\n",
                            "dists/bookworm/Release" => "old release\n")
    expect(File.exist?(work)).to be(false)
  end

  it "says what to do when the switch itself fails, and keeps the ready copy for the next publish" do
    allow(File).to receive(:rename).and_call_original
    allow(File).to receive(:rename).with(File.join(work, "dists"), anything).and_raise(Errno::EIO)
    expect { publish }.to raise_error(Relspec::PublishError, "cannot switch #{@dir} to the published state in " \
                                                             "#{work}: Input/output error; fix that and publish again " \
                                                             "(it finishes the switch, or puts back what it had replaced)")
    expect(File.exist?(File.join(work, "READY"))).to be(true)
    allow(File).to receive(:rename).and_call_original
    expect(transaction.recover).to eq(:finished)
    expect(live).to include("db/packages.db" => "new db\n", "dists/bookworm/Release" => "new release\n")
  end

  it "refuses the marker of an earlier relspec's publish, changing nothing and saying what to do" do
    File.write(File.join(@dir, described_class::OLD_MARKER), "")
    before = live
    expect { transaction.recover }.to raise_error(Relspec::PublishError, /a publish by an earlier relspec was interrupted here.*If `reprepro -b #{@dir} check` succeeds/)
    expect(live).to eq(before)
  end
end
