# frozen_string_literal: true

require "fileutils"
require "open3"

# Installs built .debs into a throwaway root instead of the machine's
# system, and runs commands that see them at their real paths.
#
# Packages of a release live under /opt/rock/<release>/…. Every command runs
# in a private mount namespace (`unshare --mount`, root only, as CI runs) in
# which the throwaway root's opt/ is bind-mounted over /opt: programs see the
# installed packages where they belong, and the host's /opt never changes.
# "Installing" unpacks the .deb there (dpkg-deb -x): dpkg's own database is
# the machine's and is left alone, so Depends are not checked here (the
# builds in a clean chroot and apt's simulations check them).
class UnpackedRoot
  # The environment of a user, not of this test run: under `bundle exec`
  # every ruby child would see only the test bundle's gems.
  OUTSIDE_BUNDLE = %w[RUBYOPT RUBYLIB BUNDLE_GEMFILE BUNDLER_SETUP BUNDLE_BIN_PATH BUNDLER_VERSION GEM_HOME GEM_PATH
                      BUNDLER_ORIG_PATH BUNDLER_ORIG_RUBYOPT BUNDLER_ORIG_RUBYLIB BUNDLER_ORIG_GEM_PATH
                      BUNDLER_ORIG_GEM_HOME BUNDLER_ORIG_BUNDLE_GEMFILE BUNDLER_ORIG_BUNDLE_BIN_PATH
                      BUNDLER_ORIG_BUNDLER_SETUP BUNDLER_ORIG_BUNDLER_VERSION BUNDLER_ORIG_MANPATH]
                   .to_h { |name| [name, nil] }.freeze

  class Failed < StandardError
  end

  attr_reader :root

  # +dir+: an empty folder for the root.
  def initialize(dir)
    @dir = dir
    @root = File.join(dir, "root")
    FileUtils.mkdir_p(File.join(@root, "opt"))
  end

  def install(deb)
    output, status = Open3.capture2e("dpkg-deb", "-x", deb, @root)
    raise Failed, "dpkg-deb -x #{deb} failed:\n#{output}" unless status.success?
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
end
