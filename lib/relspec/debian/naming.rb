# frozen_string_literal: true

module Relspec
  module Debian
    # Debian package names of a release, compatible with the existing Rock
    # releases (docs/compile.md, Names and versions): `rock-master-20.06-base-types`,
    # `rock-master-20.06-ruby-tools-orocos.rb`, `rock-master-20.06-meta-rock.core`.
    module Naming
      module_function

      # `/` and `_` become `-`, then lowercase; dots stay.
      def canonical(package_name)
        package_name.tr("/_", "--").downcase
      end

      # The name Debian gives the package of gem +gem+ (ruby-concurrent-ruby
      # for concurrent-ruby; Debian sometimes differs, see docs/compile.md).
      # The gem's name in an osdeps gem entry, which may carry a version
      # constraint ("rice<4.0.0").
      def gem_name(entry)
        entry[/\A[^<>=~!\s]+/]
      end

      def distribution_gem(gem)
        "ruby-#{canonical(gem)}"
      end

      # The name package +package_name+ (of +build_type+) has in release
      # +release+ whose Debian names start with +prefix+.
      def deb_name(prefix:, release:, package_name:, build_type:)
        kind =
          case build_type
          when "ruby", "gem" then "ruby-"
          when "meta" then "meta-"
          else ""
          end
        "#{prefix}-#{release}-#{kind}#{canonical(package_name)}"
      end

      # The files of a source package, as dpkg-source names them: the epoch
      # of a version never appears in a file name.
      def orig_tarball(source, upstream)
        "#{source}_#{upstream}.orig.tar.gz"
      end

      def debian_tarball(source, version)
        "#{source}_#{without_epoch(version)}.debian.tar.xz"
      end

      def dsc(source, version)
        "#{source}_#{without_epoch(version)}.dsc"
      end

      def without_epoch(version)
        version.to_s.sub(/\A\d+:/, "")
      end
    end
  end
end
