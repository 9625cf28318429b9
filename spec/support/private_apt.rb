# frozen_string_literal: true

require "fileutils"
require "open3"

# apt-get with its own sources, lists and cache in a test folder, reading
# this machine's dpkg status: how a user's machine would see the given
# repositories, without changing the host's apt configuration.
class PrivateApt
  # +dir+: an empty folder; +sources+: lines of a sources.list
  # ("deb [trusted=yes] file:/… bookworm main").
  def initialize(dir, sources)
    @dir = dir
    %w[lists/partial cache/archives/partial parts].each { |sub| FileUtils.mkdir_p(File.join(dir, sub)) }
    File.write(File.join(dir, "sources.list"), sources.map { |line| "#{line}\n" }.join)
  end

  def self.source(repository, codename, keyring: nil)
    option = keyring ? "signed-by=#{keyring}" : "trusted=yes"
    "deb [#{option}] file:#{repository} #{codename} main"
  end

  def options
    ["-o", "Dir::Etc::sourcelist=#{File.join(@dir, 'sources.list')}", "-o", "Dir::Etc::sourceparts=#{File.join(@dir, 'parts')}",
     "-o", "Dir::State::Lists=#{File.join(@dir, 'lists')}", "-o", "Dir::Cache=#{File.join(@dir, 'cache')}",
     "-o", "Dir::Cache::pkgcache=", "-o", "Dir::Cache::srcpkgcache=", "-o", "APT::Sandbox::User=root",
     "-o", "Debug::NoLocking=1"]
  end

  def update
    Open3.capture2e("apt-get", *options, "update")
  end

  # [output, status] of apt-get install --simulate +packages+.
  def simulate(*packages)
    Open3.capture2e("apt-get", *options, "install", "--simulate", "--no-install-recommends", *packages)
  end
end
