# frozen_string_literal: true

require "spec_helper"
require_relative "../../support/machine_apt"

# The user-side tests' guard of this machine's apt (issue 46: a relspec-*.list
# left by something else turned a fresh-clone CI run red on a diff), on a
# machine root of its own: a folder with etc/apt and var/lib/apt/lists, and
# a dpkg that is a list (a real purge of the machine's packages is what
# these tests must never do to what they did not install).
RSpec.describe MachineApt, :tmpdir do
  # dpkg as a list of installed packages
  let(:dpkg) do
    Class.new do
      attr_reader :list, :purged

      def initialize(list)
        @list = list
        @purged = []
      end

      def installed(pattern) = @list.select { |name| File.fnmatch(pattern, name) }.sort

      def purge(names)
        @purged += names
        @list -= names
      end
    end.new(%w[rock-demo-old vim])
  end

  def path(relative) = File.join(@dir, relative)

  def write(relative, content, mode = 0o644)
    FileUtils.mkdir_p(File.dirname(path(relative)))
    File.write(path(relative), content)
    File.chmod(mode, path(relative))
  end

  # every file below the root with its content and mode
  def tree
    Dir.glob("**/*", base: @dir).select { |name| File.file?(path(name)) }.sort
       .to_h { |name| [name, [File.read(path(name)), File.stat(path(name)).mode & 0o777]] }
  end

  before do
    write("etc/apt/sources.list.d/debian.sources", "Types: deb\n")
    write("etc/apt/sources.list.d/relspec-other.list", "deb [trusted=yes] http://127.0.0.1:1/other bookworm main\n")
    write("etc/apt/keyrings/relspec-other.gpg", "key", 0o600)
    write("var/lib/apt/lists/deb.debian.org_Packages", "Package: a\n")
  end

  it "names what was there before the test plainly, and puts back exactly what the test changed" do
    said = []
    before = tree
    machine = described_class.new("rock-demo-*", root: @dir, dpkg: dpkg, say: ->(text) { said << text })
    expect(said).to eq(["MachineApt: before this test, this machine already had #{path('etc/apt/keyrings/relspec-other.gpg')}, " \
                        "#{path('etc/apt/sources.list.d/relspec-other.list')}, the package rock-demo-old, which the test " \
                        "did not make (an earlier run killed before it cleaned up, or a workspace of this machine); the " \
                        "test leaves them as it found them"])

    # what a user-side test does: its release's source and lists, apt
    # installing, and the documented removal of every relspec-*.list
    write("etc/apt/sources.list.d/relspec-demo-child.list", "deb [trusted=yes] http://127.0.0.1:9/demo-child bookworm main\n")
    write("etc/apt/sources.list.d/debian.sources", "Types: deb deb-src\n")
    File.delete(path("etc/apt/sources.list.d/relspec-other.list"))
    File.delete(path("etc/apt/keyrings/relspec-other.gpg"))
    write("var/lib/apt/lists/127.0.0.1:9_demo-child_Packages", "Package: rock-demo-child-a\n")
    dpkg.list << "rock-demo-child-a"

    expect(machine.unexplained_changes).to eq(
      ["added #{path('etc/apt/sources.list.d/relspec-demo-child.list')}",
       "changed #{path('etc/apt/sources.list.d/debian.sources')}", "list 127.0.0.1:9_demo-child_Packages"]
    )
    machine.restore
    expect(tree).to eq(before)
    expect([dpkg.purged, dpkg.list]).to eq([["rock-demo-child-a"], %w[rock-demo-old vim]])
  end

  it "says nothing on a machine that has nothing of relspec's" do
    FileUtils.rm_f([path("etc/apt/sources.list.d/relspec-other.list"), path("etc/apt/keyrings/relspec-other.gpg")])
    dpkg.list.delete("rock-demo-old")
    said = []
    machine = described_class.new("rock-demo-*", root: @dir, dpkg: dpkg, say: ->(text) { said << text })
    expect([said, machine.note, machine.changes]).to eq([[], nil, []])
  end
end
