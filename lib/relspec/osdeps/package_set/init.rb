# frozen_string_literal: true

# relspec's package set (written by `relspec osdeps package-set`; do not
# edit, regenerate it). It makes an autoproj workspace use a relspec release's
# binaries instead of building those packages from source:
#
#   autoproj/relspec.yml         release: <name>     (which release; required)
#   autoproj/deb_blacklist.yml   [names or patterns]  (built from source, with
#                                                     everything that needs them)
#
# On each run it chooses the release's packages for this system, gives them to
# autoproj as OS packages, points apt at the release's repositories (and its
# ancestors') and adds the installed packages' env.yml to the workspace's
# environment. It writes nothing into this package set except state/.

require_relative "lib/relspec/osdeps/package_set/activation"

RelspecPackageSet::Activation.new(Autoproj.workspace, __dir__).run
