# frozen_string_literal: true

require "spec_helper"
require_relative "../support/demo_child_dumps"
require "tmpdir"
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

  include DemoChildDumps

  let(:micro) { '<field name="microseconds" type="/int64_t" offset="0"></field>' }
  let(:abi_dir) { DemoChildDumps::ABI_DIR }

  it "sums up the ABI verdicts of the release's dumps against its ancestor's published ones" do
    Dir.mktmpdir("relspec-cli-report") do |root|
      demo_child_built(root, registry(16, "#{micro}<field name=\"flags\" type=\"/int64_t\" offset=\"8\"></field>"))
      demo_base_published(root, registry(8, micro))

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
