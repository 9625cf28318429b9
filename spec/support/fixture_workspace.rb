# frozen_string_literal: true

require "fileutils"

# What the workspaces made from ../shared/fixtures/rock-repos share: where
# the bundles are, the workspace root under a temporary base, and writing
# its files. The including class defines PACKAGES (autoproj name =>
# [bundle, folder under src/]).
module FixtureWorkspace
  # RELSPEC_ROCK_REPOS: where they are when the checkout has no ../shared
  # beside it (a git worktree in another folder)
  BUNDLES = ENV.fetch("RELSPEC_ROCK_REPOS") { File.expand_path("../../../shared/fixtures/rock-repos", __dir__) }

  attr_reader :root

  def initialize(base)
    @root = File.join(File.expand_path(base), "workspace")
  end

  def source_dir(name)
    File.join(root, "src", self.class::PACKAGES.fetch(name).last)
  end

  private

  def write(path, content)
    full = File.join(root, path)
    FileUtils.mkdir_p(File.dirname(full))
    File.write(full, content)
  end
end
