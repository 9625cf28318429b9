# frozen_string_literal: true

require "digest"
require_relative "control"
require_relative "provenance"
require_relative "rules"
require_relative "environment"
require_relative "debhelper"

module Relspec
  module Debian
    # The debian/ folder of one package built in a release, from ERB
    # templates per build type (3.0 (quilt); the debhelper compat level of
    # the target distribution, whose features the templates keep to).
    #
    # Input: a BuildInput alone (the catalog Package, its Debian name and
    # version, the target, the release's settings, its dependencies as
    # decided on the target, its OS dependencies resolved for the codename,
    # its defines and extension task as the plan resolved them). Each part
    # has its presenter: Control, Provenance, Rules, Environment.
    class DebianDir
      # Stands for the version in the debian/ whose digest decides the
      # revision (the digest must not depend on what it decides).
      VERSION_PLACEHOLDER = "@RELSPEC_VERSION@"

      # +input+: BuildInput; +version+: the PackageVersion, or nil for the
      # digest's rendering.
      def self.render(input, version:)
        new(input).render(version)
      end

      def initialize(input)
        @in = input
      end

      # {relative path => [content, mode]}
      def render(version)
        control = Control.new(@in)
        provenance = Provenance.new(@in)
        environment = Environment.new(@in)
        files = {
          "control" => control.control,
          "changelog" => provenance.changelog((version || VERSION_PLACEHOLDER).to_s),
          "copyright" => provenance.copyright,
          "rules" => Rules.new(@in).rules,
          "source/format" => "3.0 (quilt)\n",
          "env.sh" => environment.env_sh,
          "env.yml" => environment.env_yml,
          "relspec.yml" => environment.relspec_yml,
          "#{@in.deb_name}.lintian-overrides" => control.lintian_overrides
        }
        compat = @in.debhelper_compat
        files["compat"] = "#{compat}\n" if Debhelper.compat_file?(compat)
        files.to_h { |path, content| [path, [content, path == "rules" ? 0o755 : 0o644]] }
      end

      # What debian/ is made of, independent of the revision: when it changes
      # for the same upstream version, the revision goes up.
      def self.digest(files)
        Digest::SHA256.hexdigest(files.sort.map { |path, (content, mode)| "#{path}\0#{mode}\0#{content}" }.join("\0"))
      end
    end
  end
end
