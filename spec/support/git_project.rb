# frozen_string_literal: true

require "open3"

# A real git repository around a test project (specs/, releases/), with a
# fixed identity and dates so commits are the same on every run.
module GitProject
  ENVIRONMENT = {
    "GIT_AUTHOR_NAME" => "Release Maintainer", "GIT_AUTHOR_EMAIL" => "maintainer@example.org",
    "GIT_COMMITTER_NAME" => "Release Maintainer", "GIT_COMMITTER_EMAIL" => "maintainer@example.org",
    "GIT_AUTHOR_DATE" => "2021-01-01T00:00:00Z", "GIT_COMMITTER_DATE" => "2021-01-01T00:00:00Z",
    "GIT_CONFIG_NOSYSTEM" => "1", "GIT_CONFIG_GLOBAL" => File::NULL, "GIT_TERMINAL_PROMPT" => "0"
  }.freeze

  module_function

  def git(dir, *args)
    out, err, status = Open3.capture3(ENVIRONMENT, "git", "-C", dir, *args)
    raise "git #{args.join(' ')} failed in #{dir}: #{err}" unless status.success?

    out
  end

  def init(dir)
    git(dir, "init", "--quiet", "--initial-branch=main")
  end

  def commit_all(dir, message)
    git(dir, "add", "-A")
    git(dir, "commit", "--quiet", "--allow-empty", "-m", message)
  end
end
