# frozen_string_literal: true

require "spec_helper"

# Every file of spec/fixtures/specs/bad with a .err companion must be
# rejected by the real CLI with exactly that message, exit 1, no output on
# stdout and no backtrace. The .err files are the reviewed contract of our
# error messages: change them only on purpose.
RSpec.describe "relspec validate on the bad-spec corpus" do
  corpus = File.join(CliRunner::ROOT, "spec", "fixtures", "specs", "bad")
  cases = Dir.glob(File.join(corpus, "*.err")).sort

  it "has at least 30 cases" do
    expect(cases.size).to be >= 30
  end

  # One relspec process per file, as a user runs it; several at once, so
  # the corpus costs the machine's cores rather than 60 start-ups in a row.
  parallel_runs = 3

  before(:all) do
    relspec_runs # made before the threads share it
    queue = Queue.new
    cases.each { |file| queue << File.basename(file, ".err") }
    queue.close
    @runs = {}
    Array.new(parallel_runs) do
      Thread.new do
        while (name = queue.pop)
          @runs[name] = relspec("validate", "spec/fixtures/specs/bad/#{name}.yml")
        end
      end
    end.each(&:join)
  end

  cases.each do |expected_file|
    name = File.basename(expected_file, ".err")
    it "rejects #{name}" do
      run = @runs.fetch(name)
      expect(run.stderr).to eq(File.read(expected_file))
      expect(run.exit_code).to eq(1)
      expect(run.stdout).to eq("")
      expect(run.stderr).not_to match(/\.rb:\d+:in /)
    end
  end

  it "accepts the helper parent the bad specs inherit from" do
    run = relspec("validate", "spec/fixtures/specs/bad/base-ok.yml")
    expect(run.exit_code).to eq(0), run.stderr
  end

  it "reports every bad file in one run, each error once" do
    files = cases.map { |file| "spec/fixtures/specs/bad/#{File.basename(file, '.err')}.yml" }
    run = relspec("validate", *files)
    expect(run.exit_code).to eq(1)
    expected = cases.flat_map { |file| File.read(file).lines.grep_v(/^\d+ errors?/) }.uniq
    expected.each { |line| expect(run.stderr).to include(line) }
  end
end
