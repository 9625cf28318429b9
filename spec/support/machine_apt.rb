# frozen_string_literal: true

require "fileutils"
require "open3"

# This machine's apt configuration and installed packages, for the test
# that installs a release the way a user's autoproj does (as root, on this
# machine): #restore removes what was added since #initialize — apt sources
# and keyrings, apt lists of the test's repositories, and the packages whose
# names match +packages+ — and puts back any source file that was changed.
class MachineApt
  CONFIG_DIRS = %w[/etc/apt/sources.list.d /etc/apt/keyrings].freeze
  LISTS = "/var/lib/apt/lists"

  # +packages+: a dpkg-query pattern ("rock-demo-*").
  def initialize(packages)
    @packages = packages
    @config = CONFIG_DIRS.to_h { |dir| [dir, snapshot(dir)] }
    @lists = File.directory?(LISTS) ? Dir.children(LISTS) : []
  end

  # Installed packages matching the pattern.
  def installed
    output, = Open3.capture2("dpkg-query", "-W", "-f", "${Package} ${db:Status-Status}\n", @packages,
                             err: File::NULL)
    output.lines.filter_map { |line| line.split.first if line.split.last == "installed" }.sort
  end

  # How this machine's apt sources and keyrings differ, byte for byte,
  # from #initialize's, and the lists of 127.0.0.1 repositories apt holds
  # that it did not hold then: ["added PATH", "changed PATH", "removed
  # PATH", "list NAME"].
  def changes
    @config.flat_map do |dir, files|
      current = snapshot(dir)
      (current.keys - files.keys).map { |path| "added #{path}" } +
        (files.keys - current.keys).map { |path| "removed #{path}" } +
        (files.keys & current.keys).reject { |path| files[path] == current[path] }.map { |path| "changed #{path}" }
    end.sort + (Dir.children(LISTS) - @lists).grep(/\A127\.0\.0\.1/).sort.map { |name| "list #{name}" }
  end

  def restore
    installed.then do |names|
      output, status = Open3.capture2e({ "DEBIAN_FRONTEND" => "noninteractive" }, "apt-get", "purge", "-y", "-q", *names)
      warn "MachineApt: purging #{names.join(' ')} failed:\n#{output}" unless names.empty? || status.success?
    end
    @config.each do |dir, files|
      current = snapshot(dir)
      (current.keys - files.keys).each { |path| File.delete(path) }
      files.each { |path, content| File.binwrite(path, content) if current[path] != content }
    end
    (Dir.children(LISTS) - @lists).each { |name| FileUtils.rm_rf(File.join(LISTS, name)) }
    Dir.rmdir("/opt/rock") if File.directory?("/opt/rock") && Dir.empty?("/opt/rock")
  end

  private

  def snapshot(dir)
    return {} unless File.directory?(dir)

    Dir.children(dir).map { |name| File.join(dir, name) }.select { |path| File.file?(path) }
       .to_h { |path| [path, File.binread(path)] }
  end
end
