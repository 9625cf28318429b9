# frozen_string_literal: true

require "spec_helper"

# Hostile local input (issue 12, cases 1, 2, 8), through the real CLI: files
# that are not regular files, a spec past the size limit, and option values
# relspec cannot use are refused with one message, exit 1, at once. The
# alias bomb, deep nesting, bad encodings and `select: [[x]]` live in the
# bad-spec corpus (spec/fixtures/specs/bad/*.err).
RSpec.describe "relspec on hostile local input", :tmpdir do
  def validate(path)
    run = relspec("validate", path, chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to eq("")
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
    run.stderr
  end

  it "refuses a spec that is a FIFO instead of waiting for a writer" do
    File.mkfifo(File.join(@dir, "fifo.yml"))
    expect(validate("fifo.yml")).to start_with("fifo.yml: error[unreadable-file]: not a regular file (fifo)\n")
  end

  it "refuses a spec linked to /dev/zero instead of reading without end" do
    File.symlink("/dev/zero", File.join(@dir, "zero.yml"))
    expect(validate("zero.yml")).to start_with("zero.yml: error[unreadable-file]: not a regular file (characterSpecial)\n")
  end

  it "refuses a spec larger than the YAML size limit without parsing it" do
    File.open(File.join(@dir, "large.yml"), "w") do |file|
      file.write("release: large\ndescription: ")
      file.write("x" * (Relspec::Yaml::Limits::MAX_BYTES + 1))
    end
    expect(validate("large.yml")).to start_with("large.yml: error[yaml-limit]: the file is larger than 16 MiB\n")
  end

  it "accepts a spec written in UTF-16 with a byte order mark" do
    File.write(File.join(@dir, "utf16.yml"), "\uFEFFrelease: utf16\ntargets: { bionic: [amd64] }\n".encode("UTF-16LE"))
    run = relspec("validate", "utf16.yml", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
  end

  [
    [%w[compile specs/x.yml --jobs -3], "--jobs must be a whole number of 1 or more, not -3"],
    [%w[compile specs/x.yml --jobs 0], "--jobs must be a whole number of 1 or more, not 0"],
    [%w[compile specs/x.yml --timeout -5], "--timeout must be a number of seconds above 0, not -5"],
    [%w[plan specs/x.yml --timeout 0], "--timeout must be a number of seconds above 0, not 0"],
    [%w[check specs/x.yml --concurrency -1], "--concurrency must be a whole number of 1 or more, not -1"],
    [%w[osdeps render specs/x.yml --timeout -1], "--timeout must be a number of seconds above 0, not -1"]
  ].each do |args, message|
    it "refuses `#{args.join(' ')}` before reading anything" do
      run = relspec(*args, chdir: @dir)
      expect([run.exit_code, run.stderr]).to eq([1, "relspec: error: #{message}\n"])
    end
  end
end
