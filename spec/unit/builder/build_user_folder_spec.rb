# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/build_user_folder"

# A folder of the chroot's build user, named in messages by what it holds
# and its setting (its ownership rules, through the compiler cache:
# spec/unit/builder/ccache_spec.rb).
RSpec.describe Relspec::Builder::BuildUserFolder do
  around do |example|
    Dir.mktmpdir("build-user-folder-unit") { |dir| @dir = dir and example.run }
  end

  it "names what it holds and its setting in every message" do
    link = File.join(@dir, "link")
    File.symlink(@dir, link)
    folder = described_class.new(link, owner: [Process.uid, Process.gid], what: "pool", variable: "POOL")
    expect { folder.prepare }.to raise_error(Relspec::BuildError, "pool folder #{link} is not a folder " \
                                                                  '(POOL chooses another, "off" none)')
    expect { described_class.from_environment({ "POOL" => "p" }, variable: "POOL", default: "/d", what: "pool", uid: 0) }
      .to raise_error(Relspec::BuildError, 'POOL=p: not an absolute folder (or "off")')
    expect(described_class.from_environment({}, variable: "POOL", default: "/d", what: "pool", uid: 0, user: "x").dir)
      .to eq("/d")
  end

  it "quotes for Perl" do
    expect(described_class.perl("it's\\here")).to eq("'it\\'s\\\\here'")
  end
end
