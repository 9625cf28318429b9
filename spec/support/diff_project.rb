# frozen_string_literal: true

require_relative "release_fixture"
require_relative "git_project"
require_relative "cli_runner"

# A release project for diff tests: the demo workspace's checkouts, the
# ancestors "base" and "other" in reprepro repositories, a child release,
# every lock written with `relspec plan --write`, all committed to git
# (main). The repositories and the workspace are not in git, as in a real
# project.
class DiffProject
  include CliRunner

  TARGETS = [%w[bionic amd64], %w[buster amd64]].freeze
  CHILD = <<~YAML
    parent: base
    targets: { bionic: [amd64] }
    pins:
      base/types: { tag: v2.0.0 }
    repository: { path: ../repos/child, trusted: true }
    maintainer: Demo <demo@example.org>
  YAML

  attr_reader :dir, :fixture

  def initialize(dir)
    @dir = dir
    @fixture = ReleaseFixture.new(dir)
    publish_base(older_logging: true)
    @fixture.repository("other", TARGETS, { "base/cmake" => {}, "data/models" => {} })
    %w[base other].each do |name|
      @fixture.spec(name, "targets: { bionic: [amd64], buster: [amd64] }\nrepository: { path: ../repos/#{name}, trusted: true }\n")
    end
    spec("child", CHILD)
    File.write(File.join(dir, ".gitignore"), "/repos/\n/ws/\n/catalog.yml\n")
    GitProject.init(dir)
    %w[base other child].each { |release| write_lock(release) }
    GitProject.commit_all(dir, "demo releases")
  end

  # The base release's repository; with +older_logging+ its base/logging
  # was built from an older commit than the workspace's.
  def publish_base(older_logging:)
    FileUtils.rm_rf(File.join(dir, "repos", "base"))
    packages = ReleaseFixture::LAYOUT.to_h { |name| [name, {}] }
    packages["base/logging"] = { commit_time: "2020-01-01T00:00:00Z" } if older_logging
    @fixture.repository("base", TARGETS, packages)
  end

  # A spec built from the workspace's checkouts (pins need them).
  def spec(name, yaml)
    @fixture.spec(name, yaml, workspace: :checkouts)
  end

  def write_lock(release)
    run = relspec("plan", "--write", "specs/#{release}.yml", chdir: dir)
    raise "plan --write #{release} failed: #{run.stderr}" unless run.status.success?
  end

  def git(*args)
    GitProject.git(dir, *args)
  end
end
