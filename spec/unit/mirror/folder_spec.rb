# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "fileutils"
require "relspec/mirror/folder"

RSpec.describe Relspec::Mirror::Folder do
  around do |example|
    Dir.mktmpdir("relspec-unit-mirror-folder") do |dir|
      @root = dir
      example.run
    end
  end

  let(:dir) { File.join(@root, "mirror") }
  let(:marker) { File.join(dir, ".relspec-mirror") }

  it "makes a new folder its own, adopts an empty one, and takes again one it made" do
    described_class.claim(dir)
    expect(Dir.children(dir)).to eq([".relspec-mirror"])
    FileUtils.mkdir_p(File.join(dir, "conf"))
    File.write(File.join(dir, "conf", "distributions"), "Codename: bookworm\n")
    expect { described_class.claim(dir) }.not_to raise_error

    empty = File.join(@root, "empty")
    FileUtils.mkdir_p(empty)
    described_class.claim(empty)
    expect(File.file?(File.join(empty, ".relspec-mirror"))).to be(true)
  end

  it "takes a mirror an earlier relspec made (mirror.yml, its conf/distributions) and marks it" do
    FileUtils.mkdir_p(File.join(dir, "conf"))
    File.write(File.join(dir, "mirror.yml"), "release: r\n")
    File.write(File.join(dir, "conf", "distributions"), "Codename: bookworm\nLabel: relspec mirror\n")
    described_class.claim(dir)
    expect(File.file?(marker)).to be(true)
  end

  it "refuses a folder it did not make, naming what it holds, and writes nothing" do
    FileUtils.mkdir_p(File.join(dir, "conf"))
    File.write(File.join(dir, "conf", "distributions"), "Codename: bookworm\nLabel: mine\n")
    File.write(File.join(dir, "mirror.yml"), "release: r\n")
    %w[db dists pool].each { |name| FileUtils.mkdir_p(File.join(dir, name)) }
    expect { described_class.claim(dir) }
      .to raise_error(Relspec::Error, "--out #{dir} is not a mirror relspec made (it holds conf, db, dists, … and no " \
                                      ".relspec-mirror): relspec mirror makes a mirror in a new or empty folder and " \
                                      "changes only the mirrors it made; choose another --out")
    expect(File.exist?(marker)).to be(false)
    File.write(File.join(@root, "file"), "")
    expect { described_class.claim(File.join(@root, "file")) }.to raise_error(Relspec::Error, /is not a folder: /)
  end

  it "refuses a marker or conf/ that is a link, naming it" do
    outside = File.join(@root, "outside")
    FileUtils.mkdir_p([dir, outside])
    File.symlink(outside, File.join(dir, "conf"))
    File.write(marker, "")
    expect { described_class.claim(dir) }
      .to raise_error(Relspec::Error, "#{dir}/conf is a symbolic link (to #{outside}): relspec mirror writes only " \
                                      "inside #{dir} and never through a link; remove the link and run again")
    File.delete(File.join(dir, "conf"))
    File.delete(marker)
    File.symlink(File.join(outside, "m"), marker)
    expect { described_class.claim(dir) }.to raise_error(Relspec::Error, /relspec-mirror is a symbolic link/)
  end
end
