# frozen_string_literal: true

require "spec_helper"
require_relative "../support/committed_releases"
require "tmpdir"
require "fileutils"
require "digest"
require "zlib"
require "json"

# The user errors of `relspec report`; the page itself is read by a browser
# in spec/relspec/publish/example_release_spec.rb.
RSpec.describe "relspec report" do
  it "refuses a release that was never compiled, saying what to run, and writes nothing" do
    with_specs("r" => "release: r\ntargets: { bookworm: [amd64] }\nworkspace: ws\n") do |_dir, root|
      run = relspec("report", "specs/r.yml", chdir: root)
      expect([run.exit_code, run.stdout, run.stderr])
        .to eq([1, "", "relspec: error: r has no releases/r/lock.yml: run `relspec compile` first\n"])
      expect(Dir.children(root)).to eq(["specs"])
    end
  end

  it "refuses a format it does not know" do
    run = relspec("report", "specs/demo-base.yml", "--format", "pdf")
    expect([run.exit_code, run.stderr]).to eq([1, "relspec: error: Expected '--format' to be one of html, json; got pdf\n"])
  end

  # The shipped demo's specs and locks, and demo-child's last build with one
  # dump: base/types's type registry (compared by relspec abi's own code,
  # no abidiff needed), whose /base/Time grew a field since demo-base.
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
  end

  # Writes +text+ gzip-compressed at +path+; returns the file's SHA256.
  def gzip(path, text)
    FileUtils.mkdir_p(File.dirname(path))
    Zlib::GzipWriter.open(path) { |gz| gz.write(text) }
    Digest::SHA256.file(path).hexdigest
  end

  def registry(size, fields)
    %(<?xml version="1.0"?>\n<typelib>\n<numeric name="/int64_t" category="sint" size="8" source_id=""></numeric>\n) +
      %(<compound name="/base/Time" size="#{size}" source_id="">#{fields}</compound>\n</typelib>\n)
  end

  let(:micro) { '<field name="microseconds" type="/int64_t" offset="0"></field>' }
  let(:abi_dir) { File.join("build", "repositories", "demo-base", "abi", "bookworm-amd64") }

  it "sums up the ABI verdicts of the release's dumps against its ancestor's published ones" do
    Dir.mktmpdir("relspec-cli-report") do |root|
      demo_child_built(root, registry(16, "#{micro}<field name=\"flags\" type=\"/int64_t\" offset=\"8\"></field>"))
      old = gzip(File.join(root, abi_dir, "rock-demo-base-base-types", "base.tlb.abi.xml.gz"), registry(8, micro))
      File.write(File.join(root, abi_dir, "index.yml"), <<~YAML)
        relspec_abi_dumps: 1
        dumps:
          - { package: base/types, source: rock-demo-base-base-types, version: 1.0-1, library: base.tlb,
              file: rock-demo-base-base-types/base.tlb.abi.xml.gz, sha256: #{old} }
      YAML

      expect(relspec("report", "specs/demo-child.yml", "--out", "out", chdir: root).exit_code).to eq(0)
      page = File.read(File.join(root, "out", "demo-child", "report", "index.html"))
      expect(page).to include("<h3>ABI against the ancestors' published dumps</h3>\n<p class=\"totals\"><span>1 changed</span></p>\n" \
                              "<ul>\n<li><span class=\"badge changed\">changed</span> <code>base.tlb</code> (base/types) " \
                              "<span class=\"muted\">against demo-base</span></li>\n</ul>")
      expect(relspec("report", "specs/demo-child.yml", "--out", "out", "--format", "json", chdir: root).exit_code).to eq(0)
      json = JSON.parse(File.read(File.join(root, "out", "demo-child", "report", "report.json")))
      expect(json["targets"].first["abi"]["counts"]).to eq("unchanged" => 0, "compatible" => 0, "changed" => 1,
                                                           "incompatible" => 0, "new" => 0)
    end
  end

  # demo-base's repository holds an ABI index relspec does not read (someone
  # else's, or a newer relspec's): no verdict can be computed.
  it "writes the page when an ancestor's ABI index is unreadable, saying why instead of the verdicts" do
    Dir.mktmpdir("relspec-cli-report") do |root|
      demo_child_built(root, registry(8, micro))
      FileUtils.mkdir_p(File.join(root, abi_dir))
      File.write(File.join(root, abi_dir, "index.yml"), "relspec_abi_dumps: 9\nentries: [<script>]\n")

      run = relspec("report", "specs/demo-child.yml", "--out", "out", chdir: root)
      expect([run.exit_code, run.stdout, run.stderr]).to eq([0, "wrote out/demo-child/report/index.html\n", ""])
      page = File.read(File.join(root, "out", "demo-child", "report", "index.html"))
      expect(page).to include("<h3>ABI against the ancestors' published dumps</h3>\n<p class=\"muted\">not computed: ")
      expect(page[/not computed: [^<]*/]).to include("abi/bookworm-amd64/index.yml:1:20: error[abi-index]: " \
                                                     "cannot read the ABI index: unknown format 9")
      expect(page).not_to include("<script>")
    end
  end
end
