# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "../../support/build_release"

# The early cutoff on a published release (docs/abi.md, "Early cutoff"):
# base/lib, a C library, and base/user, which includes its header and
# links it, built with the host backend and published into a real reprepro
# repository. A new version of base/lib from an overlay that changes a
# function body: `relspec plan` names base/user a candidate that keeps its
# published version, and `relspec build` decides base/lib's interface
# unchanged against the build it replaces, recorded with its evidence in
# build-results.yml. One that changes its header: changed.
RSpec.describe "the early cutoff on a published release", order: :defined do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-cutoff")
    @release = BuildRelease.new(@dir, "ec")
    @release.package("base/lib", cmake: "enable_language(C)\nadd_library(cut SHARED cut.c)\n" \
                                        "install(TARGETS cut LIBRARY DESTINATION lib)\ninstall(FILES cut.h DESTINATION include)",
                                 files: { "cut.c" => "#include \"cut.h\"\nint cut_value(void) { return 42; }\n",
                                          "cut.h" => "int cut_value(void);\n" })
    @release.package("base/user", dependencies: ["base/lib"])
    @release.compile(spec: "repository: { path: ../repos/ec, trusted: true }\n")
    run!("build", "specs/ec.yml", "--out", "out", "--backend", "host")
    run!("publish", "specs/ec.yml", "--out", "out")
    @first = record("base/lib")
    @first_user = record("base/user")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def run!(*args)
    run = relspec(*args, chdir: @dir)
    raise "relspec #{args.join(' ')}: #{run.stdout}#{run.stderr}" unless run.exit_code.zero?

    run
  end

  def record(package)
    YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))["packages"][@release.source(package)]
  end

  # A new version of base/lib from an overlay file over the source.
  def change(path, content)
    overlay = File.join(@dir, "overlays", "base", "lib", "files", path)
    FileUtils.mkdir_p(File.dirname(overlay))
    File.write(overlay, content)
  end

  it "records no verdict for a first build" do
    expect(@first).not_to have_key("interface")
  end

  it "names the dependent a candidate before building, and decides the body change left the interface unchanged" do
    change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 43; }\n")
    plan = run!("plan", "specs/ec.yml").stdout
    expect(plan).to match(%r{base/user +rock-ec-base-user \S+-2\n    missing in all ancestors\n    early cutoff candidate: \S+-1~bookworm stays if the interface of base/lib does not change\n})
    expect(plan).not_to match(%r{base/lib .*\n.*\n    early cutoff})
    why = run!("why", "specs/ec.yml", "base/user").stdout
    expect(why).to end_with("  missing in all ancestors\n  early cutoff candidate: #{@first_user['version']} stays if the " \
                            "interface of base/lib does not change\n")

    run!("compile", "specs/ec.yml", "--out", "out")
    run!("build", "specs/ec.yml", "--out", "out", "--backend", "host")
    body = record("base/lib")
    expect(body["version"]).not_to eq(@first["version"])
    expect(body["interface"]).to include("against" => @first["version"], "verdict" => "unchanged", "changes" => [])
    expect(body["interface"]["compared"]).to be >= 3 # the header, the library, the copyright
    # plan.yml carries the candidate; the build decides it would keep base/user's published version
    entry = YAML.safe_load(File.read(File.join(@release.target_dir, "plan.yml")))["builds"].find do |build|
      build["package"] == "base/user"
    end
    user_first = @first_user["version"]
    expect(entry["cutoff"]).to eq("keeps" => user_first, "because" => [@release.source("base/lib")])
    expect(record("base/user")["cutoff"]).to eq("keeps" => user_first, "verdict" => "keep",
                                                "reason" => "the interface of #{@release.source('base/lib')} did not change")
  end

  it "decides a header change changed the interface, naming the header, and rebuilds the candidate" do
    run!("publish", "specs/ec.yml", "--out", "out") # the body change, published as a maintainer would
    before = record("base/lib")
    published_user = record("base/user")["version"]
    change("cut.h", "int cut_value(void);\nint cut_other(void);\n")
    run!("compile", "specs/ec.yml", "--out", "out")
    build = run!("build", "specs/ec.yml", "--out", "out", "--backend", "host")
    header = record("base/lib")
    expect(header["interface"]).to include("against" => before["version"], "verdict" => "changed")
    expect(header["interface"]["changes"]).to eq(["opt/rock/ec/rock-ec-base-lib/include/cut.h: differs"])
    expect(build.stdout).to include("interface changed from #{before['version']}: opt/rock/ec/rock-ec-base-lib/include/cut.h: differs")
    expect(record("base/user")["cutoff"]).to eq("keeps" => published_user, "verdict" => "rebuild",
                                                "reason" => "the interface of #{@release.source('base/lib')} changed")
    expect(build.stdout).to include("early cutoff: rebuilt: the interface of #{@release.source('base/lib')} changed")
  end
end
