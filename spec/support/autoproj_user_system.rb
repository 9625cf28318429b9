# frozen_string_literal: true

require "bundler"
require "fileutils"
require "yaml"
require_relative "git_project"
require_relative "installed_system"

# A user's machine of another distribution than this one, for real: a clean
# system unpacked from the chroot tarball (InstalledSystem), where the user
# installs Ruby and git with apt and autoproj with gem (the versions of
# relspec's Gemfile.lock), brings an autoproj workspace, adds relspec's
# package set (a git repository, as users get it) to its manifest, chooses a
# release and runs autoproj as root. autoproj runs apt-get through sudo, in
# the system; the network is this machine's, so a repository served on
# 127.0.0.1 is the user's repository server. Nothing reaches this machine
# (every command runs in the system's own mount namespace): removing the
# folder removes it all.
class AutoprojUserSystem
  # what a Debian user installs to run autoproj (it calls apt-get through sudo)
  PACKAGES = %w[ruby ruby-dev git build-essential sudo].freeze
  GEMS = %w[autobuild autoproj].freeze
  WORKSPACE = "/ws/workspace"
  PACKAGE_SET = "/ws/package-set"

  attr_reader :system

  # +tarball+: the distribution's chroot tarball; +dir+: the system's folder.
  def initialize(tarball, dir)
    @system = InstalledSystem.new(tarball, dir)
  end

  # Ruby, git and autoproj as the user installs them; autoproj and
  # autobuild at +lockfile+'s versions.
  def install_autoproj(lockfile)
    @system.install([], packages: PACKAGES)
    @system.run!("update-ca-certificates") # the authorities InstalledSystem brought
    locked = Bundler::LockfileParser.new(File.read(lockfile)).specs.to_h { |spec| [spec.name, spec.version.to_s] }
    @system.run!('gem install --no-document "$@"', *GEMS.map { |name| "#{name}:#{locked.fetch(name)}" })
  end

  # The autoproj workspace +workspace+ (checked out, with its own package
  # sets) and the package set folder +package_set+ copied in; the package
  # set added to the manifest and +release+ chosen, the user's two steps.
  # +osdeps+: what the user's other package sets define (autoproj/ruby.osdeps).
  def add_workspace(workspace, package_set, release:, osdeps:)
    FileUtils.mkdir_p(@system.path("ws"))
    FileUtils.cp_r(workspace, @system.path(WORKSPACE))
    FileUtils.cp_r(package_set, @system.path(PACKAGE_SET))
    GitProject.init(@system.path(PACKAGE_SET))
    GitProject.commit_all(@system.path(PACKAGE_SET), "relspec's package set")
    manifest = @system.path("#{WORKSPACE}/autoproj/manifest")
    data = YAML.safe_load_file(manifest)
    data["package_sets"] << { "type" => "git", "url" => PACKAGE_SET }
    File.write(manifest, YAML.dump(data))
    File.write(@system.path("#{WORKSPACE}/autoproj/ruby.osdeps"), osdeps)
    File.write(@system.path("#{WORKSPACE}/.autoproj/config.yml"), "gems_install_path: /ws/gems\n", mode: "a")
    File.write(@system.path("#{WORKSPACE}/autoproj/relspec.yml"), "release: #{release}\n")
  end

  # autoproj +args+ in the workspace; [output, status]. git (its importer)
  # may only read local repositories.
  def autoproj(*args)
    @system.run("cd #{WORKSPACE} && autoproj \"$@\"", *args, env: { "GIT_ALLOW_PROTOCOL" => "file" })
  end

  def autoproj!(*args)
    output, status = autoproj(*args)
    raise InstalledSystem::Failed, "autoproj #{args.join(' ')} failed:\n#{output}" unless status.success?

    output
  end

  # Package => version of the installed packages matching +pattern+.
  def installed(pattern)
    output = @system.run!("dpkg-query -W -f '${db:Status-Status} ${Package} ${Version}\\n' \"$1\" || true", pattern)
    output.lines.map(&:split).select { |status, _| status == "installed" }.to_h { |_, name, version| [name, version] }
  end

  # The workspace's folders below src/ where a CMake package was configured:
  # what autoproj built from source.
  def built_from_source
    Dir.glob("**/build/CMakeCache.txt", base: @system.path("#{WORKSPACE}/src")).map { |path| path.delete_suffix("/build/CMakeCache.txt") }.sort
  end
end
