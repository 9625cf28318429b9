# frozen_string_literal: true

require "fileutils"
require "open3"

# This machine's apt configuration and installed packages, for the tests
# that install a release the way a user's autoproj does (as root, on this
# machine): #restore puts back exactly what the test changed since
# #initialize — apt sources and keyrings added, changed or removed (the
# documented removal deletes every relspec-*.list), apt lists added, and the
# packages matching +packages+ that the test installed — whatever ran before.
#
# What was there before the test and is not the test's own is named once,
# plainly (#note): relspec files in /etc/apt (another run killed before its
# restore, a workspace of this machine on a release) and release packages
# already installed. The test works around them (#unexplained_changes) and
# leaves them as it found them, instead of failing on a diff that names them
# among its own changes.
class MachineApt
  CONFIG_DIRS = %w[etc/apt/sources.list.d etc/apt/keyrings].freeze
  LISTS = "var/lib/apt/lists"
  # the names relspec's package set gives its files in /etc/apt
  RELSPEC_FILE = "relspec-*"

  # The machine's dpkg: installed packages of a pattern, and their purge.
  class Dpkg
    def installed(pattern)
      output, = Open3.capture2("dpkg-query", "-W", "-f", "${Package} ${db:Status-Status}\n", pattern, err: File::NULL)
      output.lines.filter_map { |line| line.split.first if line.split.last == "installed" }.sort
    end

    def purge(names)
      return if names.empty?

      output, status = Open3.capture2e({ "DEBIAN_FRONTEND" => "noninteractive" }, "apt-get", "purge", "-y", "-q", *names)
      warn "MachineApt: purging #{names.join(' ')} failed:\n#{output}" unless status.success?
    end
  end

  attr_reader :foreign

  # +packages+: a dpkg-query pattern ("rock-demo-*"). +root+: the machine's
  # root folder; +dpkg+: Dpkg; +say+: where #note goes (all three for
  # MachineApt's own test, spec/relspec/osdeps/machine_apt_spec.rb).
  def initialize(packages, root: "/", dpkg: Dpkg.new, say: ->(text) { warn(text) })
    @packages = packages
    @root = root
    @dpkg = dpkg
    @config = CONFIG_DIRS.to_h { |dir| [dir, snapshot(dir)] }
    @lists = lists
    @preinstalled = installed
    @foreign = @config.values.flat_map(&:keys).select { |path| File.fnmatch(RELSPEC_FILE, File.basename(path)) }.sort
    say.call(note) if note
  end

  # What was on the machine before the test that is not the test's, as one
  # line; nil when there is nothing.
  def note
    found = @foreign + @preinstalled.map { |name| "the package #{name}" }
    return nil if found.empty?

    "MachineApt: before this test, this machine already had #{found.join(', ')}, which the test did not make " \
      "(an earlier run killed before it cleaned up, or a workspace of this machine); the test leaves them as it " \
      "found them"
  end

  # Installed packages matching the pattern.
  def installed
    @dpkg.installed(@packages)
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
    end.sort + (lists - @lists).grep(/\A127\.0\.0\.1/).sort.map { |name| "list #{name}" }
  end

  # #changes but the removal of #foreign files: what the documented
  # removal (`rm -f /etc/apt/sources.list.d/relspec-*.list …`) does to
  # another release's files is not the test's to judge (#restore puts them
  # back).
  def unexplained_changes
    changes - @foreign.map { |path| "removed #{path}" }
  end

  def restore
    @dpkg.purge(installed - @preinstalled)
    @config.each do |dir, files|
      current = snapshot(dir)
      (current.keys - files.keys).each { |path| FileUtils.rm_f(path) }
      files.each do |path, (content, mode)|
        next if current[path] == [content, mode]

        File.binwrite(path, content)
        File.chmod(mode, path)
      end
    end
    (lists - @lists).each { |name| FileUtils.rm_rf(File.join(@root, LISTS, name)) }
    opt = File.join(@root, "opt", "rock")
    Dir.rmdir(opt) if File.directory?(opt) && Dir.empty?(opt)
  end

  private

  def lists
    dir = File.join(@root, LISTS)
    File.directory?(dir) ? Dir.children(dir) : []
  end

  # path => [content, mode] of the files of +dir+ (below the root).
  def snapshot(dir)
    dir = File.join(@root, dir)
    return {} unless File.directory?(dir)

    Dir.children(dir).map { |name| File.join(dir, name) }.select { |path| File.file?(path) }
       .to_h { |path| [path, [File.binread(path), File.stat(path).mode & 0o7777]] }
  end
end
