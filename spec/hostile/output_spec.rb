# frozen_string_literal: true

require "spec_helper"
require "digest"

# Damaged outputs and caches (issue 12, case 9), through the real CLI: a
# truncated .orig.tar.gz in the output is noticed by the stamp and written
# again; a damaged tarball in the orig cache is made again, with a warning
# naming the cache entry, instead of failing in tar with a hint about
# overlays. Both end with the files a clean
# compile writes.
RSpec.describe "relspec compile over damaged outputs" do
  # One fixture and one clean compile for all (they are most of the
  # time); each example starts from a copy of that compile's output.
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-output")
    @spec = ReleaseFixture.new(@dir).standalone("h", select: ["base/cmake"], targets: "bionic: [amd64, arm64]")
    run = relspec("compile", @spec, "--out", "out", "--no-check", chdir: @dir)
    raise "the clean compile failed: #{run.stderr}" unless run.exit_code.zero?

    %w[out releases].each { |name| File.rename(File.join(@dir, name), File.join(@dir, "clean-#{name}")) }
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  before do
    %w[out releases].each { |name| system("cp", "-a", File.join(@dir, "clean-#{name}"), File.join(@dir, name), exception: true) }
    @clean = files
  end

  after { FileUtils.rm_rf([File.join(@dir, "out"), File.join(@dir, "releases")]) }

  def compile
    run = relspec("compile", @spec, "--out", "out", "--no-check", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    run
  end

  def files
    Dir.glob(File.join(@dir, "out", "h", "*", "*", "*")).sort.to_h { |path| [path, Digest::SHA256.file(path).hexdigest] }
  end

  it "starts from what a compile writes: a second compile writes nothing" do
    expect(compile.stdout).not_to include("wrote")
    expect(files).to eq(@clean)
  end

  it "notices a truncated .orig.tar.gz in the output and writes the package again" do
    clean = @clean
    orig = Dir.glob(File.join(@dir, "out", "h", "bionic-amd64", "*", "*.orig.tar.gz")).first
    File.truncate(orig, File.size(orig) / 2)
    run = compile
    expect(run.stdout).to include("wrote out/h/bionic-amd64/rock-h-base-cmake")
    expect(run.stdout).not_to include("bionic-arm64")
    expect(files).to eq(clean)
  end

  it "notices an output file changed in place (same size) and writes the package again" do
    clean = @clean
    dsc = Dir.glob(File.join(@dir, "out", "h", "bionic-arm64", "*", "*.dsc")).first
    File.write(dsc, File.read(dsc).tr("a", "b"))
    run = compile
    expect(run.stdout).to include("wrote out/h/bionic-arm64/rock-h-base-cmake")
    expect(files).to eq(clean)
  end

  it "makes a damaged orig cache entry again instead of failing in tar" do
    clean = @clean
    cached = Dir.glob(File.join(@dir, "out", "h", ".orig", "*", "*.orig.tar.gz")).first
    File.binwrite(cached, File.binread(cached)[0, 40])
    FileUtils.rm_rf(Dir.glob(File.join(@dir, "out", "h", "bionic-*")))
    run = compile
    expect(files).to eq(clean)
    # said once (two targets share the entry), naming the cache, not the overlays
    entry = cached.delete_prefix("#{@dir}/")
    expect(run.stderr.scan("warning: the orig cache entry #{entry} was damaged").size).to eq(1), run.stderr
    expect(run.stderr).not_to include("overlay")
    expect(compile.stderr).not_to include("damaged")
  end
end
