# frozen_string_literal: true

require "digest"
require "fileutils"
require "zlib"
require_relative "committed_releases"
require_relative "demo_child_plan"

# The shipped demo's specs and locks in a folder of the test's, with
# demo-child's last build holding one ABI dump (base/types's type registry,
# compared by relspec abi's own code, no abidiff needed) and demo-base's
# repository publishing one of its own: `relspec abi` and `relspec report`
# of demo-child compare the two.
module DemoChildDumps
  ABI_DIR = File.join("build", "repositories", "demo-base", "abi", "bookworm-amd64")

  # demo-child built in +root+, its dump the registry +registry+ (text).
  def demo_child_built(root, registry)
    CommittedReleases.project(root, %w[demo-base demo-child])
    target = File.join(root, "out", "demo-child", "bookworm-amd64")
    dump = gzip(File.join(target, "results", "rock-demo-child-base-types", "base.tlb.abi.xml.gz"), registry)
    File.write(File.join(target, "build-results.yml"), <<~YAML)
      relspec_build_results: 1
      release: demo-child
      target: bookworm/amd64
      backend: host
      packages:
        rock-demo-child-base-types:
          package: base/types
          version: 2.0-1~bookworm
          status: built
          files:
            - { name: results/rock-demo-child-base-types/base.tlb.abi.xml.gz, sha256: #{dump}, size: 1 }
    YAML
    DemoChildPlan.write(target)
  end

  # demo-base's repository in +root+ publishing the registry +registry+
  # (text) of base/types; the published dump's path.
  def demo_base_published(root, registry)
    path = File.join(root, ABI_DIR, "rock-demo-base-base-types", "base.tlb.abi.xml.gz")
    old = gzip(path, registry)
    File.write(File.join(root, ABI_DIR, "index.yml"), <<~YAML)
      relspec_abi_dumps: 1
      dumps:
        - { package: base/types, source: rock-demo-base-base-types, version: 1.0-1, library: base.tlb,
            file: rock-demo-base-base-types/base.tlb.abi.xml.gz, sha256: #{old} }
    YAML
    path
  end

  # Writes +text+ gzip-compressed at +path+; returns the file's SHA256.
  def gzip(path, text)
    FileUtils.mkdir_p(File.dirname(path))
    Zlib::GzipWriter.open(path) { |gz| gz.write(text) }
    Digest::SHA256.file(path).hexdigest
  end

  # A registry of /base/Time (+size+ bytes, +fields+ its <field> elements).
  def registry(size, fields)
    %(<?xml version="1.0"?>\n<typelib>\n<numeric name="/int64_t" category="sint" size="8" source_id=""></numeric>\n) +
      %(<compound name="/base/Time" size="#{size}" source_id="">#{fields}</compound>\n</typelib>\n)
  end
end
