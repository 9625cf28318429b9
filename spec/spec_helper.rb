# frozen_string_literal: true

$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec"
require "tmpdir"
require_relative "support/cli_runner"
require_relative "support/spec_writer"
require_relative "support/workspace_helpers"
require_relative "support/apt_repository_builder"
require_relative "support/http_server"
require_relative "support/launchpad_server"
require_relative "support/streamed_body"
require_relative "support/fixtures_needed"
require_relative "support/release_file_editor"
require_relative "support/release_fixture"
require_relative "support/gem_builder"
require_relative "support/unpacked_root"
require_relative "support/private_apt"
require_relative "support/git_project"
require_relative "support/diff_project"
require_relative "support/large_locks"

# In-process runs cache like CLI runs do: in a folder of the test run
# (and so do the sbuild builds' compiler cache, and what the tests spawn).
ENV["XDG_CACHE_HOME"] = CliRunner::CACHE
ENV.update(CliRunner::CCACHE_ENV)

RSpec.configure do |config|
  config.expect_with(:rspec) { |c| c.syntax = :expect }
  config.disable_monkey_patching!
  config.order = :random
  Kernel.srand config.seed
  config.include CliRunner
  config.include SpecWriter
  config.include WorkspaceHelpers
  config.include FixturesNeeded

  # `RSpec.describe X, :tmpdir`: each example gets an empty folder in @dir.
  config.around(:each, :tmpdir) do |example|
    Dir.mktmpdir("relspec-test") do |dir|
      @dir = dir
      example.run
    end
  end

  # The hostile-input corpus: every example of its files is :hostile, so a
  # new case cannot be left out of the guards below.
  config.define_derived_metadata(file_path: %r{spec/(hostile/|cli/bad_specs_spec)}) { |meta| meta[:hostile] = true }

  # Runs of a before(:context) (copied into every example) are judged in
  # each example; an example's own runs go to a list of its own.
  config.before(:each, :hostile) { @relspec_runs = relspec_runs.dup }

  # Whatever the input, relspec never exits 70 nor shows a backtrace
  # without --debug, and uses no more than this memory (issues 12 and 24;
  # docs/limits.md), in every run, whether the example looks at it or not.
  config.after(:each, :hostile) do
    broken = relspec_runs.filter_map { |run| run.broken_promise&.then { |why| "relspec #{run.args.join(' ')}: #{why}:\n#{run.stderr}" } }
    expect(broken).to be_empty, broken.join("\n")
    expect(relspec_runs.filter_map(&:max_rss_kib)).to all(be < CliRunner::HOSTILE_MAX_RSS_KIB)
  end
end
