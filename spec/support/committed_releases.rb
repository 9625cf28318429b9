# frozen_string_literal: true

require "fileutils"
require "open3"

# The demo's releases/ as committed. bin/test's examples process runs
# bin/demo (readme_spec), which rewrites releases/ in the checkout while it
# compiles and publishes (a lock says `decision: build` until publish), so a
# test in another process that reads the demo's locks takes them from git,
# not from the working tree.
module CommittedReleases
  # The committed text of releases/+path+ ("demo-base/lock.yml").
  def self.read(path)
    text, errors, status = Open3.capture3("git", "-C", CliRunner::ROOT, "show", "HEAD:releases/#{path}")
    raise "releases/#{path} is not committed: #{errors}" unless status.success?

    text
  end

  # A project in +root+ with the demo's specs of +releases+ and their
  # committed locks.
  def self.project(root, releases)
    FileUtils.mkdir_p(File.join(root, "specs"))
    releases.each do |release|
      FileUtils.cp(File.join(CliRunner::ROOT, "specs", "#{release}.yml"), File.join(root, "specs"))
      FileUtils.mkdir_p(File.join(root, "releases", release))
      copy("#{release}/lock.yml", File.join(root, "releases", release, "lock.yml"))
    end
  end

  # Writes the committed releases/+path+ to +target+; +target+.
  def self.copy(path, target)
    File.write(target, read(path))
    target
  end
end
