# frozen_string_literal: true

require "spec_helper"

# Issue 46, case 14: values typed on the command line were echoed raw in
# relspec's messages (`bookworm/amd64^[[31mX is not a target…`), where an
# escape sequence recolours or clears the terminal and a newline forges a
# line of relspec's own output. Values from specs and indices were already
# escaped (Printable); now every message is.
RSpec.describe "relspec with control characters in its command-line values", :tmpdir do
  let(:esc) { "\e[31m" }

  it "escapes --target in the not-a-target error, and keeps a newline in it from forging a line" do
    run = relspec("build", "specs/demo-base.yml", "--out", @dir, "--target", "bookworm/amd64#{esc}X\nrelspec: ok")
    expect([run.exit_code, run.stderr]).to eq(
      [1, "relspec: error: bookworm/amd64\\e[31mX\\nrelspec: ok is not a target of demo-base (bookworm/amd64, trixie/amd64)\n"]
    )
  end

  it "escapes a target that is not codename/arch" do
    run = relspec("build", "specs/demo-base.yml", "--out", @dir, "--target", "bookworm#{esc}")
    expect([run.exit_code, run.stderr]).to eq(
      [1, "relspec: error: a target is written codename/arch (e.g. bionic/amd64), not \"bookworm\\e[31m\"\n"]
    )
  end

  it "escapes an unknown option, an enum value Thor refuses and a spec path that cannot be read" do
    option = relspec("plan", "specs/demo-base.yml", "--jobs#{esc}")
    source = relspec("check", "specs/demo-base.yml", "--source", "apt#{esc}")
    path = relspec("plan", "specs/demo-base#{esc}.yml")
    expect([option.exit_code, option.stderr]).to eq([1, "relspec: error: unknown option --jobs\\e[31m\n"])
    expect([source.exit_code, source.stderr])
      .to eq([1, "relspec: error: Expected '--source' to be one of auto, apt, launchpad; got apt\\e[31m\n"])
    expect([path.exit_code, path.stderr]).to eq(
      [1, "specs/demo-base\\e[31m.yml: error[unreadable-file]: cannot read the file: No such file or directory\n" \
          "1 error in 1 file\n"]
    )
  end

  it "escapes an --out folder in what it says it wrote" do
    run = relspec("report", "specs/demo-base.yml", "--out", File.join(@dir, "x#{esc}"))
    expect([run.exit_code, run.stdout]).to eq([0, "wrote #{@dir}/x\\e[31m/demo-base/report/index.html\n"])
  end

  # A value with a newline in a message of several lines (a path repeated
  # in a diagnostic, a ref) would still have forged a line: such values are
  # refused as names or printed whole, on one line.
  it "keeps every other command-line value on its line: osdeps select, osdeps index and diff --base" do
    forged = "v\nrelspec: forged#{esc}"
    shown = "v\\nrelspec: forged\\e[31m"
    select = %w[osdeps select --release demo-base --arch amd64 --os debian:12,bookworm --data] + [File.join(CliRunner::ROOT, "releases")]
    runs = {
      "--release \"#{shown}\" is not a release name" => select.map { |arg| arg == "demo-base" ? forged : arg },
      "--arch \"#{shown}\" is not a Debian architecture name" => select.map { |arg| arg == "amd64" ? forged : arg },
      "--os \"v\\nrelspec:\\e[31m\" holds control characters" =>
        select.map { |arg| arg == "debian:12,bookworm" ? "v\nrelspec:#{esc}" : arg },
      "#{shown}/ holds no release spec" => ["osdeps", "index", "--specs", forged],
      "#{shown} is not a commit of the git repository at ." => ["diff", "--base", forged]
    }
    runs.each do |message, args|
      run = relspec(*args, chdir: args.first == "diff" ? CliRunner::ROOT : @dir)
      expect([run.exit_code, run.stderr]).to eq([1, "relspec: error: #{message}\n"]), args.inspect
    end
    missing = relspec(*select.take(8), "--data", File.join(@dir, forged), chdir: @dir)
    expect([missing.exit_code, missing.stderr.lines.size]).to eq([1, 2]), missing.stderr
    expect(missing.stderr).to include("no osdeps file #{@dir}/#{shown}/demo-base/osdeps/demo-base-amd64.yml\n")
    expect(Dir.children(@dir)).to eq([])
  end

  it "escapes the lock's path that plan --write names, below a spec folder the command line named" do
    # made at a plain path (autoproj reads it there), then renamed
    ReleaseFixture.new(File.join(@dir, "proj"))
                  .spec("h", "select: [base/cmake]\ntargets: { bionic: [amd64] }\nmaintainer: Demo <demo@example.org>\n")
    File.rename(File.join(@dir, "proj"), File.join(@dir, "proj#{esc}"))
    run = relspec("plan", "proj#{esc}/specs/h.yml", "--write", chdir: @dir)
    expect([run.exit_code, run.stderr.lines.last]).to eq([0, "wrote proj\\e[31m/releases/h/lock.yml\n"]), run.stderr
  end
end
