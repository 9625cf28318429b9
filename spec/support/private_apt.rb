# frozen_string_literal: true

require "fileutils"
require "open3"

# apt-get with its own sources, lists and cache in a test folder, reading
# a copy of this machine's dpkg status without the release's packages: how a
# user's machine that has none of the release would see the given
# repositories, without changing the host's apt configuration.
#
# Without them because tests in another process of bin/test install releases
# into this machine meanwhile (package_set_workspace_spec's rock-demo-*, as a
# user's autoproj does): read live, the status then says "already the newest
# version" or "not fully installed" for the very packages a test asks apt to
# install.
class PrivateApt
  MACHINE_STATUS = "/var/lib/dpkg/status"
  # the tests' releases are named rock-<release>-…
  RELEASE_PACKAGE = /\APackage: rock-/

  # +dir+: an empty folder; +sources+: lines of a sources.list
  # ("deb [trusted=yes] file:/… bookworm main"); +machine_status+: the dpkg
  # status file to copy.
  def initialize(dir, sources, machine_status: MACHINE_STATUS)
    @dir = dir
    %w[lists/partial cache/archives/partial parts].each { |sub| FileUtils.mkdir_p(File.join(dir, sub)) }
    File.write(File.join(dir, "sources.list"), sources.map { |line| "#{line}\n" }.join)
    stanzas = File.read(machine_status).split(/\n{2,}/).reject { |stanza| stanza.match?(RELEASE_PACKAGE) }
    File.write(status_path, stanzas.map { |stanza| "#{stanza.chomp}\n\n" }.join)
  end

  def self.source(repository, codename, keyring: nil)
    option = keyring ? "signed-by=#{keyring}" : "trusted=yes"
    "deb [#{option}] file:#{repository} #{codename} main"
  end

  def options
    ["-o", "Dir::Etc::sourcelist=#{File.join(@dir, 'sources.list')}", "-o", "Dir::Etc::sourceparts=#{File.join(@dir, 'parts')}",
     "-o", "Dir::State::Lists=#{File.join(@dir, 'lists')}", "-o", "Dir::Cache=#{File.join(@dir, 'cache')}",
     "-o", "Dir::Cache::pkgcache=", "-o", "Dir::Cache::srcpkgcache=", "-o", "APT::Sandbox::User=root",
     "-o", "Debug::NoLocking=1", "-o", "Dir::State::status=#{status_path}"]
  end

  def update
    Open3.capture2e("apt-get", *options, "update")
  end

  # [output, status] of apt-get install --simulate +packages+.
  def simulate(*packages)
    Open3.capture2e("apt-get", *options, "install", "--simulate", "--no-install-recommends", *packages)
  end

  private

  def status_path
    File.join(@dir, "status")
  end
end
