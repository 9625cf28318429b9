# frozen_string_literal: true

require "fileutils"
require "open3"
require "tmpdir"
require "relspec/abi/installed_files"

# Real gcc, objcopy (as dh_strip splits the debug information off) and
# dpkg-deb: a program and a Ruby-extension-like plugin built twice from the
# same code in two build folders differ in their bytes only where they name
# their debug files (.gnu_debuglink's CRC, the build id), which is what made
# the Rock core's base_types_ruby.so count as a changed interface after a
# body-only change of base/types (performance.md, session 17).
RSpec.describe Relspec::Abi::InstalledFiles do
  around do |example|
    Dir.mktmpdir("relspec-elf") do |dir|
      @dir = dir
      example.run
    end
  end

  def run(*command, chdir: @dir)
    output, status = Open3.capture2e(*command, chdir: chdir)
    raise "#{command.join(' ')}: #{output}" unless status.success?
  end

  # A .deb holding usr/bin/tool and usr/lib/plugin.so built in the build
  # folder +name+ from +code+, stripped with a debug link as dh_strip does.
  def deb(name, code)
    build = File.join(@dir, name)
    root = File.join(@dir, "#{name}-root")
    FileUtils.mkdir_p([build, File.join(root, "DEBIAN"), File.join(root, "usr/bin"), File.join(root, "usr/lib")])
    File.write(File.join(build, "tool.c"), "#include <stdio.h>\nint main(void) { puts(\"#{code}\"); return 0; }\n")
    File.write(File.join(build, "plugin.c"), "int Init_plugin(void) { return #{code.length}; }\n")
    run("gcc", "-g", "-O2", "-o", "tool", "tool.c", chdir: build)
    run("gcc", "-g", "-O2", "-shared", "-fPIC", "-o", "plugin.so", "plugin.c", chdir: build)
    { "tool" => "usr/bin/tool", "plugin.so" => "usr/lib/plugin.so" }.each do |file, target|
      run("objcopy", "--only-keep-debug", file, "#{file}.debug", chdir: build)
      run("objcopy", "--strip-debug", "--add-gnu-debuglink=#{file}.debug", file, File.join(root, target), chdir: build)
    end
    File.write(File.join(root, "DEBIAN/control"),
               "Package: tool\nVersion: 1\nArchitecture: amd64\nMaintainer: t <t@t.invalid>\nDescription: t\n")
    run("dpkg-deb", "--root-owner-group", "--build", root, File.join(@dir, "#{name}.deb"))
    File.join(@dir, "#{name}.deb")
  end

  def bytes(deb, path)
    out = File.join(@dir, "x-#{File.basename(deb)}")
    run("dpkg-deb", "-x", deb, out)
    File.binread(File.join(out, path))
  end

  it "compares ELF files without their debug links: the same code is the same, other code differs" do
    first = deb("build-one", "hello")
    second = deb("build-two-elsewhere", "hello")
    changed = deb("build-three", "hello, world")
    expect(bytes(first, "usr/bin/tool")).not_to eq(bytes(second, "usr/bin/tool"))

    one, two, three = [first, second, changed].map { |path| described_class.of([path]) }
    expect(two).to eq(one)
    expect(three["usr/bin/tool"]).not_to eq(one["usr/bin/tool"])
    expect(three["usr/lib/plugin.so"]).not_to eq(one["usr/lib/plugin.so"])
  end
end
