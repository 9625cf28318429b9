# frozen_string_literal: true

require "fileutils"
require "open3"

# Builds emitted source packages with dpkg-buildpackage and installs the
# resulting .debs into a throwaway root instead of the machine's system.
#
# Packages of a release live under /opt/rock/<release>/…, and each build
# needs its dependencies there. Every command runs in a private mount
# namespace (`unshare --mount`, root only, as CI runs) in which the
# throwaway root's opt/ is bind-mounted over /opt: builds and programs see
# the installed packages at their real paths, and the host's /opt never
# changes. "Installing" unpacks the .deb there (dpkg-deb -x): dpkg's own
# database is the machine's and is left alone, so Depends are not checked.
#
# This is the one place to swap for `relspec build --backend host` (or
# sbuild) when the builder exists.
class HostBuild
  # The environment of a builder, not of this test run: under `bundle exec`
  # every ruby child would see only the test bundle's gems.
  OUTSIDE_BUNDLE = %w[RUBYOPT RUBYLIB BUNDLE_GEMFILE BUNDLER_SETUP BUNDLE_BIN_PATH BUNDLER_VERSION GEM_HOME GEM_PATH
                      BUNDLER_ORIG_PATH BUNDLER_ORIG_RUBYOPT BUNDLER_ORIG_RUBYLIB BUNDLER_ORIG_GEM_PATH
                      BUNDLER_ORIG_GEM_HOME BUNDLER_ORIG_BUNDLE_GEMFILE BUNDLER_ORIG_BUNDLE_BIN_PATH
                      BUNDLER_ORIG_BUNDLER_SETUP BUNDLER_ORIG_BUNDLER_VERSION BUNDLER_ORIG_MANPATH]
                   .to_h { |name| [name, nil] }.freeze

  Failed = Class.new(StandardError)

  attr_reader :root

  # +dir+: an empty folder for the root, the unpacked sources and the .debs.
  def initialize(dir)
    @dir = dir
    @root = File.join(dir, "root")
    FileUtils.mkdir_p(File.join(@root, "opt"))
    FileUtils.mkdir_p(File.join(dir, "work"))
  end

  # Builds the source package of +dsc+ and installs its .debs; returns their paths.
  def build_and_install(dsc)
    debs = build(dsc)
    debs.each { |deb| install(deb) }
    debs
  end

  def build(dsc)
    source = File.basename(dsc, ".dsc").sub(/_[^_]*\z/, "")
    work = File.join(@dir, "work")
    check(Open3.capture2e("dpkg-source", "-x", dsc, source, chdir: work), "dpkg-source -x #{dsc}")
    before = Dir.glob(File.join(work, "*.deb"))
    check(run({ "DEB_BUILD_OPTIONS" => "nocheck noddebs parallel=2" }, "dpkg-buildpackage", "-us", "-uc", "-b", "-d",
              chdir: File.join(work, source)), "dpkg-buildpackage of #{source}")
    (Dir.glob(File.join(work, "*.deb")) - before).sort
  end

  def install(deb)
    check(Open3.capture2e("dpkg-deb", "-x", deb, @root), "dpkg-deb -x #{deb}")
  end

  # Runs +command+ with the installed packages at /opt; returns [output, status].
  def run(env, *command, chdir: @dir)
    Open3.capture2e(OUTSIDE_BUNDLE.merge(env), "unshare", "--mount", "--propagation", "private", "sh", "-c",
                    'mount --bind "$0" /opt && exec "$@"', File.join(@root, "opt"), *command, chdir: chdir)
  end

  # A shell script in a clean environment (what a user's login shell would
  # have), with the installed packages at /opt.
  def shell(script, chdir: @dir)
    clean = ENV.keys.to_h { |name| [name, nil] }
    run(clean.merge("PATH" => "/usr/local/bin:/usr/bin:/bin", "HOME" => @dir, "LANG" => "C.UTF-8"),
        "bash", "-c", script, chdir: chdir)
  end

  private

  def check(result, what)
    output, status = result
    raise Failed, "#{what} failed:\n#{output.lines.last(40).join}" unless status.success?

    output
  end
end
