# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "../../support/build_release"

# `relspec build` decides the early cutoff's verdict of a package when its
# build finishes (docs/abi.md, "Early cutoff"): the new build against the
# one it replaces, still in the target folder, recorded with its evidence
# in build-results.yml. A library's new version from an overlay that
# changes a function body leaves its interface unchanged; one that changes
# its header changes it.
RSpec.describe "relspec build: the early cutoff's verdict of each rebuilt package" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-cutoff")
    @release = BuildRelease.new(@dir, "ec")
    @release.package("base/lib", cmake: "enable_language(C)\nadd_library(cut SHARED cut.c)\n" \
                                        "install(TARGETS cut LIBRARY DESTINATION lib)\ninstall(FILES cut.h DESTINATION include)",
                                 files: { "cut.c" => "#include \"cut.h\"\nint cut_value(void) { return 42; }\n",
                                          "cut.h" => "int cut_value(void);\n" })
    @release.compile
    build!
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def build!
    run = relspec("build", "specs/ec.yml", "--out", "out", "--backend", "host", chdir: @dir)
    raise "relspec build: #{run.stdout}#{run.stderr}" unless run.exit_code.zero?

    YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))["packages"][@release.source("base/lib")]
  end

  # A new version of base/lib from an overlay file over the source.
  def rebuild_with(path, content)
    overlay = File.join(@dir, "overlays", "base", "lib", "files", path)
    FileUtils.mkdir_p(File.dirname(overlay))
    File.write(overlay, content)
    compile = relspec("compile", "specs/ec.yml", "--out", "out", chdir: @dir)
    raise "relspec compile: #{compile.stderr}" unless compile.exit_code.zero?

    build!
  end

  it "records no verdict for a first build, unchanged for a body change and changed for a header change" do
    first = YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))["packages"][@release.source("base/lib")]
    expect(first).not_to have_key("interface")

    body = rebuild_with("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 43; }\n")
    expect(body["version"]).not_to eq(first["version"])
    expect(body["interface"]).to include("against" => first["version"], "verdict" => "unchanged", "changes" => [])
    expect(body["interface"]["compared"]).to be >= 3 # the header, the library, the copyright

    header = rebuild_with("cut.h", "int cut_value(void);\nint cut_other(void);\n")
    expect(header["interface"]).to include("against" => body["version"], "verdict" => "changed")
    expect(header["interface"]["changes"]).to eq(["opt/rock/ec/rock-ec-base-lib/include/cut.h: differs"])
  end
end
