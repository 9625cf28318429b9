# frozen_string_literal: true

require "spec_helper"

# The suite runs relspec forked from a preloaded relspec (PreloadedRelspec):
# what a user sees must be what a process of its own shows.
RSpec.describe "relspec runs forked from the preloaded relspec" do
  def spawned(*args, **options)
    ENV["RELSPEC_TEST_SPAWN"] = "1"
    relspec(*args, **options)
  ensure
    ENV.delete("RELSPEC_TEST_SPAWN")
  end

  it "give the same output and exit status as a process of its own" do
    [%w[validate spec/fixtures/specs/bad/base-ok.yml], %w[validate spec/fixtures/specs/bad/no-such-file.yml],
     %w[--version], %w[no-such-command], %w[plan --target]].each do |args|
      preloaded = relspec(*args)
      own = spawned(*args)
      expect(preloaded.status).to be_a(PreloadedRelspec::Status)
      expect(own.status).to be_a(Process::Status)
      seen = [preloaded.stdout, preloaded.stderr, preloaded.exit_code]
      expect(seen).to eq([own.stdout, own.stderr, own.exit_code]), "relspec #{args.join(' ')}"
    end
  end

  it "runs in the working folder and environment it is given, and reports its peak memory" do
    Dir.mktmpdir("relspec-preloaded") do |dir|
      FileUtils.mkdir_p(File.join(dir, "specs"))
      File.write(File.join(dir, "specs", "x.yml"), "release: x\n")
      run = relspec("validate", "specs/x.yml", chdir: dir, env: { "NO_COLOR" => "1" })
      expect(run.status).to be_a(PreloadedRelspec::Status)
      expect([run.stdout, run.stderr]).to eq(spawned("validate", "specs/x.yml", chdir: dir).then { |own| [own.stdout, own.stderr] })
      expect(run.max_rss_kib).to be > 10_000
    end
  end

  it "starts a process of its own for a variable read while Ruby starts, and for a umask" do
    expect(relspec("--version", env: { "LANG" => "C" }).status).to be_a(Process::Status)
    expect(relspec("--version", umask: 0o077).status).to be_a(Process::Status)
  end
end
