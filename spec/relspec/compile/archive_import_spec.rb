# frozen_string_literal: true

require "spec_helper"
require "zlib"
require "rubygems/package"
require_relative "../../support/http_server"

# A package autoproj imports from a tarball (`type: archive`), served by a
# real HTTP server on 127.0.0.1: it is planned with a version made of the
# archive's modification time (Last-Modified), the lock records its
# checksum, the plan says where it came from, and two compiles give the
# same .orig bytes.
RSpec.describe "archive imports" do
  modified = Time.utc(2021, 3, 4, 5, 6, 7)

  before(:all) do
    @base = Dir.mktmpdir("relspec-archive")
    served = File.join(@base, "served")
    FileUtils.mkdir_p(served)
    @archive = File.join(served, "tarball-1.2.tar.gz")
    write_tarball(@archive, "tarball-1.2/CMakeLists.txt" => "project(tarball)\n", "tarball-1.2/README" => "tarball\n")
    File.utime(modified, modified, @archive)
    @back = File.join(served, "back-1.0.tar.gz") # its time moves back (issue 46, case 13)
    write_tarball(@back, "back-1.0/CMakeLists.txt" => "project(back)\n")
    @server = HttpServer.new(served)
    builder = WorkspaceBuilder.new(@base)
    builder.package("base/cmake", type: :cmake, date: "2020-06-01T10:00:00Z")
    # bad input: an archive the server does not have, and a package set
    # patch that names a file outside the package
    builder.autobuild("import_package 'external/tarball'\nimport_package 'external/missing'\n" \
                      "import_package 'external/escape'\nimport_package 'external/level'\nimport_package 'external/back'\n" \
                      "import_package 'external/slow'\n")
    root = builder.create
    File.write(File.join(root, "autoproj", "evil.patch"), "--- ../../etc/passwd\n+++ ../../etc/passwd\n@@ -1 +1 @@\n-a\n+b\n")
    # made by `diff -ru a/ b/`, given at autobuild's default level 0 (issue 46, case 16)
    File.write(File.join(root, "autoproj", "level.patch"),
               "--- a/CMakeLists.txt\n+++ b/CMakeLists.txt\n@@ -1 +1 @@\n-project(tarball)\n+project(patched)\n")
    File.write(File.join(root, "autoproj", "overrides.yml"), <<~YAML)
      overrides:
        - external/tarball: { type: archive, url: "#{@server.url}/tarball-1.2.tar.gz" }
        - external/missing: { type: archive, url: "#{@server.url}/missing-1.0.tar.gz" }
        - external/escape: { type: archive, url: "#{@server.url}/tarball-1.2.tar.gz", patches: [$AUTOPROJ_ROOT/autoproj/evil.patch] }
        - external/back: { type: archive, url: "#{@server.url}/back-1.0.tar.gz" }
        - external/level: { type: archive, url: "#{@server.url}/tarball-1.2.tar.gz", patches: [$AUTOPROJ_ROOT/autoproj/level.patch] }
        - external/slow: { type: archive, url: "#{@server.url}/slow/tarball-1.2.tar.gz" }
    YAML
    # what autoproj's import left: the archive unpacked in the source folder
    %w[tarball missing escape level back slow].each do |name|
      FileUtils.mkdir_p(File.join(root, "src", "external", name))
      File.write(File.join(root, "src", "external", name, "CMakeLists.txt"), "project(#{name})\n")
    end
    FileUtils.mkdir_p(File.join(@base, "specs"))
    { "r" => "tarball", "missing" => "missing", "escape" => "escape", "level" => "level", "back" => "back",
      "slow" => "slow" }.each do |spec, name|
      File.write(File.join(@base, "specs", "#{spec}.yml"), <<~YAML)
        release: #{spec}
        maintainer: Rock Packaging <rock@example.org>
        workspace: ../workspace
        select: [external/#{name}]
        targets: { bookworm: [amd64] }
      YAML
    end
  end

  after(:all) do
    @server&.stop
    FileUtils.rm_rf(@base) if @base
  end

  def write_tarball(path, files)
    File.open(path, "wb") do |file|
      Zlib::GzipWriter.wrap(file) do |gzip|
        Gem::Package::TarWriter.new(gzip) do |tar|
          files.each { |name, content| tar.add_file_simple(name, 0o644, content.bytesize) { |io| io.write(content) } }
        end
      end
    end
  end

  it "plans it with the archive's modification time, says where it came from and locks its checksum" do
    run = relspec("plan", "specs/r.yml", "--write", chdir: @base)
    expect(run.exit_code).to eq(0), run.stderr
    sha256 = Digest::SHA256.file(@archive).hexdigest
    expect(run.stdout).to include("external/tarball is imported from the archive #{@server.url}/tarball-1.2.tar.gz " \
                                  "(sha256 #{sha256}, modified 2021-03-04T05:06:07Z)")
    lock = YAML.safe_load_file(File.join(@base, "releases", "r", "lock.yml"))
    expect(lock.dig("packages", "external/tarball")).to include("sha256" => sha256, "commit_time" => "2021-03-04T05:06:07Z")
    expect(lock.dig("packages", "external/tarball", "version")).to end_with("20210304.050607")
  end

  it "emits the same .orig twice, holding the archive's tree dated by the archive" do
    origs = %w[one two].map do |out|
      run = relspec("compile", "specs/r.yml", "--out", out, chdir: @base)
      expect(run.exit_code).to eq(0), run.stderr
      Dir[File.join(@base, out, "**", "*.orig.tar.gz")].first
    end
    expect(File.binread(origs[0])).to eq(File.binread(origs[1]))
    listing, = Open3.capture2("tar", "--utc", "-tvzf", origs[0])
    expect(listing).to include("/CMakeLists.txt").and include("/README")
    expect(listing.lines.grep(/README/).first).to include("2021-03-04 05:06")
  end

  it "refuses an archive the server does not have, and a package set patch leaving the package, without output" do
    run = relspec("plan", "specs/missing.yml", chdir: @base)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("error[archive-import]: external/missing: #{@server.url}/missing-1.0.tar.gz answered 404")
    run = relspec("compile", "specs/escape.yml", "--out", "escape", chdir: @base)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("error[package-set-patch]: package set patch autoproj/evil.patch names no file inside " \
                                  "the package's folder")
    expect(run.stderr).not_to match(/backtrace|\.rb:\d/)
    expect(Dir[File.join(@base, "escape", "**", "*.dsc")]).to eq([])
  end

  # compile's --timeout reaches the archive's download (Http::Download):
  # each attempt waits --timeout for an answer, three attempts, then one
  # error naming them, long before the server's 4 s or relspec's default 10 s
  it "gives up on a server that does not answer after compile's --timeout, three times" do
    @server.fail(%r{\A/slow/}, :stall, seconds: 4)
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    run = relspec("compile", "specs/slow.yml", "--out", "slow", "--timeout", "1", chdir: @base)
    elapsed = Process.clock_gettime(Process::CLOCK_MONOTONIC) - started
    expect(run.exit_code).to eq(1), run.stderr
    url = Regexp.escape("#{@server.url}/slow/tarball-1.2.tar.gz")
    expect(run.stderr).to match(%r{error\[archive-import\]: external/slow: cannot fetch #{url}: no answer within 1 s per read \(after 3 attempts, [\d.]+ s in all\)})
    expect(@server.requests.count("/slow/tarball-1.2.tar.gz")).to eq(3)
    expect(elapsed).to be < 9
    expect(Dir[File.join(@base, "slow", "**", "*.dsc")]).to eq([])
  end

  # Issue 46, case 13: the version followed the archive's time back
  # (0.20990101 → 0.20210101), which apt never takes for an upgrade. Each
  # run fetches the archive again (a cache of its own), as after the cache
  # entry was deleted.
  it "keeps an archive import's version rising when the archive's time moves back, and warns" do
    lock = File.join(@base, "releases", "back", "lock.yml")
    cache = nil
    plan = lambda do |time|
      File.utime(time, time, @back)
      cache = Dir.mktmpdir("cache", @base)
      run = relspec("plan", "specs/back.yml", "--write", chdir: @base, env: { "XDG_CACHE_HOME" => cache })
      expect(run.exit_code).to eq(0), run.stderr
      [YAML.safe_load_file(lock).dig("targets", "bookworm/amd64", "external/back", "version"), run.stdout]
    end
    first, = plan.call(Time.utc(2099, 1, 1))
    back, said = plan.call(Time.utc(2021, 1, 1))
    again, = plan.call(Time.utc(2021, 1, 1))
    # dpkg-source takes the raised version
    compile = relspec("compile", "specs/back.yml", "--out", "back", chdir: @base, env: { "XDG_CACHE_HOME" => cache })
    expect(compile.exit_code).to eq(0), compile.stderr
    expect(Dir[File.join(@base, "back", "**", "*.dsc")].map { |path| File.basename(path) })
      .to eq(["rock-back-external-back_0.20990101.000000+really0.20210101.000000-1~bookworm.dsc"])
    later, quiet = plan.call(Time.utc(2100, 1, 1))
    expect([first, back, again, later]).to eq(%w[0.20990101.000000-1~bookworm 0.20990101.000000+really0.20210101.000000-1~bookworm
                                                 0.20990101.000000+really0.20210101.000000-1~bookworm 0.21000101.000000-1~bookworm])
    expect(said).to include("external/back: its archive's time gives 0.20210101.000000, below 0.20990101.000000, which the " \
                            "release already gave it (bookworm/amd64); versioned 0.20990101.000000+really0.20210101.000000, " \
                            "so that apt takes it as an upgrade")
    expect(quiet).not_to include("archive's time gives")
  end

  # Issue 46, case 16: dpkg-source stopped at "can't find file to patch",
  # after the .orig and debian/ were made.
  it "refuses a package set patch whose file the package does not have at its level, naming patch, file and level" do
    run = relspec("compile", "specs/level.yml", "--out", "level", chdir: @base)
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr.lines.grep_v(/WARN: .* does not have a manifest/).join).to eq(
      "autoproj/level.patch: error[package-set-patch]: package set patch autoproj/level.patch changes a/CMakeLists.txt " \
      "or b/CMakeLists.txt, which the package's source does not have at level 0 (patch -p0)\n  " \
      "hint: fix the patch's file names, or its level in the package set (`patches: [[file, level]]`; autobuild's " \
      "default level is 0, a patch made by `diff -ru a/ b/` needs 1)\n1 error in 1 file\n"
    )
    expect(Dir[File.join(@base, "level", "**", "*.{dsc,orig.tar.gz}")]).to eq([])
  end
end
