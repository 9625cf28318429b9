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

      # Gems Debian does not package as ruby-<gem>: tools whose package
      # carries the command's name, and gems whose name already says Ruby.
      # Each is the binary package holding the gem's specification in
      # Debian's archive (checked on bookworm and jammy; docs/compile.md).
      IRREGULAR_GEMS = {
        "concurrent-ruby" => "ruby-concurrent", "rake" => "rake", "rake-compiler" => "rake-compiler",
        "thin" => "thin", "yard" => "yard"
      }.freeze

      # Every Debian name distribution_gem can give.
      DISTRIBUTION_GEMS = /\A(?:ruby-|(?:#{IRREGULAR_GEMS.values.map { |name| Regexp.escape(name) }.join('|')})\z)/

      # The gem's name in an osdeps gem entry, which may carry a version
      # constraint ("rice<4.0.0").
      def gem_name(entry)
        entry[/\A[^<>=~!\s]+/]
      end

      # The name Debian gives the package of gem +gem+ (an osdeps entry's
      # constraint is not part of it): ruby-<gem> unless IRREGULAR_GEMS says otherwise.
      def distribution_gem(gem)
        name = gem_name(gem)
        IRREGULAR_GEMS.fetch(name) { "ruby-#{canonical(name)}" }
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
