# frozen_string_literal: true

require "spec_helper"
require "tmpdir"
require "fileutils"
require "digest"

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

  # The shipped demo's specs and locks, demo-child's last build with one ABI
  # dump, and demo-base's repository holding an ABI index relspec does not
  # read (someone else's, or a newer relspec's): no verdict can be computed.
  it "writes the page when an ancestor's ABI index is unreadable, saying why instead of the verdicts" do
    Dir.mktmpdir("relspec-cli-report") do |root|
      FileUtils.mkdir_p(File.join(root, "specs"))
      %w[demo-base demo-child].each do |release|
        FileUtils.cp(File.join(CliRunner::ROOT, "specs", "#{release}.yml"), File.join(root, "specs"))
        FileUtils.mkdir_p(File.join(root, "releases", release))
        FileUtils.cp(File.join(CliRunner::ROOT, "releases", release, "lock.yml"), File.join(root, "releases", release))
      end
      target = File.join(root, "out", "demo-child", "bookworm-amd64")
      FileUtils.mkdir_p(File.join(target, "results", "rock-demo-child-base-types"))
      File.write(File.join(target, "results", "rock-demo-child-base-types", "libbase-types.so.abi.xml.gz"), "dump")
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
              - { name: results/rock-demo-child-base-types/libbase-types.so.abi.xml.gz, sha256: #{Digest::SHA256.hexdigest('dump')}, size: 4 }
      YAML
      index = File.join(root, "build", "repositories", "demo-base", "abi", "bookworm-amd64", "index.yml")
      FileUtils.mkdir_p(File.dirname(index))
      File.write(index, "relspec_abi_dumps: 9\nentries: [<script>]\n")

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
