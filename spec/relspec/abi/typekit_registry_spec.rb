# frozen_string_literal: true

require "spec_helper"
require "json"
require_relative "../../support/build_release"

# A typekit's type registry kept and compared: a package that installs an
# oroGen registry (share/orogen/std.tlb, written as typelib writes one) is
# built into a parent release, published, then rebuilt by a child whose
# overlay replaces the registry with one where /base/Time gained a field.
# (A real oroGen typekit takes minutes to build here: spec/toolchain builds
# base/orogen/std once; this test keeps CI cheap with a CMake package that
# installs the registry file, through the same build, dump and publish.)
RSpec.describe "relspec abi on a typekit's type registry" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-abi-typekit")
    fixtures = File.expand_path("../../fixtures/abi", __dir__)
    @release = BuildRelease.new(@dir, "tk")
    @release.package("base/cmake", cmake: "")
    @release.package("test/typekit", dependencies: ["base/cmake"], cmake: "install(FILES std.tlb DESTINATION share/orogen)",
                                     files: { "std.tlb" => File.read(File.join(fixtures, "std.tlb")) })
    @release.compile(spec: "repository: { path: ../repos/tk, trusted: true }\n")
    run!("build", "specs/tk.yml", "--out", "out", "--backend", "host")
    run!("publish", "specs/tk.yml", "--out", "out")
    File.write(File.join(@dir, "specs", "child.yml"), <<~YAML)
      release: child
      parent: tk
      workspace: ../ws/workspace
      blacklist:
        - { match: test/typekit, reason: its registry grows }
    YAML
    overlay = File.join(@dir, "overlays", "test", "typekit", "files", "std.tlb")
    FileUtils.mkdir_p(File.dirname(overlay))
    FileUtils.cp(File.join(fixtures, "std-grown.tlb"), overlay)
    run!("compile", "specs/child.yml", "--out", "out")
    run!("build", "specs/child.yml", "--out", "out", "--backend", "host")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def run!(*args)
    run = relspec(*args, chdir: @dir)
    raise "relspec #{args.join(' ')}: #{run.stdout}#{run.stderr}" unless run.status.success?

    run
  end

  it "keeps the registry with the build, publishes it, and shows the added field as a layout change" do
    index = YAML.safe_load_file(File.join(@dir, "repos", "tk", "abi", "bookworm-amd64", "index.yml"))
    expect(index["dumps"].map { |entry| entry.values_at("package", "library") }).to eq([["test/typekit", "std.tlb"]])

    run = relspec("abi", "specs/child.yml", "--out", "out", "--fail-on", "changed", chdir: @dir)
    expect(run.status.exitstatus).to eq(1), run.stderr
    expect(run.stdout).to eq(<<~TEXT)
      child bookworm/amd64: 1 library: 1 changed
        std.tlb (test/typekit): changed against tk
          Types changes summary: 0 Removed, 1 Changed, 0 Added types
          [C] /base/Time:
            size 8 -> 16 bytes
            field microseconds offset 0 -> 8
            field flags (/int64_t) added at offset 0
    TEXT
    entry = JSON.parse(run!("abi", "specs/child.yml", "--out", "out", "--format", "json").stdout)["targets"]["bookworm/amd64"].first
    expect(entry.values_at("package", "library", "verdict", "against")).to eq(["test/typekit", "std.tlb", "changed", "tk"])
  end
end
