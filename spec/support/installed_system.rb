# frozen_string_literal: true

require "fileutils"
require "open3"

# A clean Debian system made from the chroot tarball `relspec build
# --backend sbuild` keeps in its cache, in which built .debs are really
# installed: apt-get takes the .deb files and fetches their Depends from
# the distribution's archive (the tarball's own apt sources), dpkg unpacks
# them and runs their maintainer scripts. A package that forgets a runtime
# dependency fails here, where UnpackedRoot (dpkg-deb -x on the host) would
# not notice.
#
# Commands run through `chroot`, root only (as CI runs), in a private mount
# namespace with /proc and /dev of their own, so nothing is mounted on the
# host after a command ends and the folder can simply be removed.
class InstalledSystem
  class Failed < StandardError
  end

  PATH = "/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin"
  LOCAL_AUTHORITIES = "/usr/local/share/ca-certificates"

  attr_reader :root

  # +tarball+: a chroot tarball (.tar.zst); +dir+: the system's folder. A
  # system left in +dir+ by an earlier run (a kept RELSPEC_TOOLCHAIN_DIR) is
  # removed first: unpacked over, its dpkg state (e.g. dbus's statoverride of
  # a group the fresh /etc/group lacks) stops the next install.
  def initialize(tarball, dir)
    @root = File.join(dir, "root")
    FileUtils.rm_rf(@root)
    FileUtils.mkdir_p(@root)
    output, status = Open3.capture2e("tar", "--zstd", "-xf", tarball, "-C", @root)
    raise Failed, "cannot unpack #{tarball}:\n#{output}" unless status.success?

    # the name server of now, not of the day the tarball was made
    FileUtils.cp("/etc/resolv.conf", File.join(@root, "etc", "resolv.conf")) if File.file?("/etc/resolv.conf")
    # and the certificate authorities this machine adds (a proxy's, which
    # HTTPS downloads such as rubygems.org's pass through): the system's
    # ca-certificates takes them in when it is installed or when
    # update-ca-certificates runs
    local = Dir.glob(File.join(LOCAL_AUTHORITIES, "*.crt"))
    FileUtils.mkdir_p(path(LOCAL_AUTHORITIES))
    FileUtils.cp(local, path(LOCAL_AUTHORITIES))
  end

  # Installs the .deb files +debs+ and the distribution packages named in
  # +packages+, with every dependency, as a user would with apt.
  def install(debs, packages: [])
    run!("apt-get update -q && apt-get install -y -q --no-install-recommends \"$@\"",
         *stage(debs, "debs"), *packages, env: { "DEBIAN_FRONTEND" => "noninteractive" })
  end

  # Installs the .gem files +gems+ into the system's own gem folder (as
  # `gem install` as root would), without their dependencies.
  def install_gems(gems)
    run!('gem install --local --ignore-dependencies --no-document "$@"', *stage(gems, "gems"))
  end

  # Runs the bash +script+ in the system as a user's login shell would
  # (clean environment, HOME=/root), with +args+ as $1…; [output, status].
  def run(script, *args, env: {})
    environment = { "PATH" => PATH, "HOME" => "/root", "LANG" => "C.UTF-8" }.merge(env)
                                                                            .map { |name, value| "#{name}=#{value}" }
    Open3.capture2e({}, "unshare", "--mount", "--propagation", "private", "--fork", "--pid", "sh", "-c",
                    'mount -t proc proc "$0/proc" && mount --rbind /dev "$0/dev" && exec chroot "$@"', @root,
                    @root, "env", "-i", *environment, "bash", "-c", script, "bash", *args, unsetenv_others: true)
  end

  # #run, raising Failed with the output when +script+ fails; the output.
  def run!(script, *args, env: {})
    output, status = run(script, *args, env: env)
    raise Failed, "#{script} failed:\n#{output}" unless status.success?

    output
  end

  # Copies +files+ into /tmp/<folder> of the system; their paths there.
  def stage(files, folder)
    FileUtils.mkdir_p(path("tmp/#{folder}"))
    FileUtils.cp(files, path("tmp/#{folder}"))
    files.map { |file| "/tmp/#{folder}/#{File.basename(file)}" }
  end

  # The host path of +path+ inside the system.
  def path(path)
    File.join(@root, path)
  end
end
