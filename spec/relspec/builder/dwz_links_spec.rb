# frozen_string_literal: true

require "fileutils"
require "open3"
require "tmpdir"
require "relspec/builder/dwz_links"

# Real gcc, dwz (debhelper's dh_dwz), objcopy and abidw: two libraries
# sharing a header get a dwz multifile, laid out as a -dbgsym .deb unpacks.
# The Rock core's base/types (its library and its Ruby extension) is such a
# package: abidw made no dump of libbase-types.so before (performance.md,
# session 17).
RSpec.describe Relspec::Builder::DwzLinks do
  around do |example|
    Dir.mktmpdir("relspec-dwz") do |dir|
      @dir = dir
      example.run
    end
  end

  def run(*command)
    output, status = Open3.capture2e(*command, chdir: @dir)
    raise "#{command.join(' ')}: #{output}" unless status.success?

    output
  end

  def build_id(file)
    run("readelf", "-n", file)[/Build ID: (\h+)/, 1]
  end

  # liba.so and libb.so built with -g, their shared debug information moved
  # by dwz into root/usr/lib/debug/.dwz/…/pkg.debug, liba's own debug file
  # at .build-id/<xx>/<rest>.debug and its stripped library in root/lib.
  def packaged_tree
    File.write(File.join(@dir, "s.h"), "struct shape { int sides; double length; struct shape *next; };\n")
    File.write(File.join(@dir, "a.c"), "#include \"s.h\"\nint sides(const struct shape *s) { return s->sides; }\n")
    File.write(File.join(@dir, "b.c"), "#include \"s.h\"\nint count(const struct shape *s) { return s ? 1 : 0; }\n")
    %w[a b].each { |name| run("gcc", "-g", "-O0", "-shared", "-fPIC", "-Wl,--build-id", "-o", "lib#{name}.so", "#{name}.c") }
    FileUtils.mkdir_p(File.join(@dir, "root/usr/lib/debug/.dwz/x86_64-linux-gnu"))
    run("dwz", "-m", "root/usr/lib/debug/.dwz/x86_64-linux-gnu/pkg.debug",
        "-M", "/usr/lib/debug/.dwz/x86_64-linux-gnu/pkg.debug", "liba.so", "libb.so")
    id = build_id("liba.so")
    FileUtils.mkdir_p(File.join(@dir, "root/usr/lib/debug/.build-id", id[0, 2]))
    FileUtils.mkdir_p(File.join(@dir, "root/lib"))
    run("objcopy", "--only-keep-debug", "liba.so", "root/usr/lib/debug/.build-id/#{id[0, 2]}/#{id[2..]}.debug")
    run("objcopy", "--strip-debug", "liba.so", "root/lib/liba.so")
    File.join(@dir, "root/usr/lib/debug")
  end

  def abidw(debug_root)
    _, status = Open3.capture2e("abidw", "--debug-info-dir", debug_root, "--out-file", File.join(@dir, "a.xml"),
                                File.join(@dir, "root/lib/liba.so"))
    status.success?
  end

  it "links a dwz multifile by its build id, without which abidw cannot read the library's debug information" do
    debug_root = packaged_tree
    multifile = File.join(debug_root, ".dwz/x86_64-linux-gnu/pkg.debug")
    expect(abidw(debug_root)).to be(false)

    id = build_id(multifile)
    expect(described_class.add(debug_root)).to eq([File.join(debug_root, ".build-id", id[0, 2], "#{id[2..]}.debug")])
    expect(File.realpath(File.join(debug_root, ".build-id", id[0, 2], "#{id[2..]}.debug"))).to eq(File.realpath(multifile))
    expect(abidw(debug_root)).to be(true)
    expect(File.read(File.join(@dir, "a.xml"))).to include("shape")
    expect(described_class.add(debug_root)).to eq([])
  end
end
