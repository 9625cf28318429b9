# frozen_string_literal: true

module Relspec
  class Catalog
    # Tells apart the prefixes of packages that share one in the workspace.
    # A package set may give a package another's prefix (rock.core:
    # `pkg.define 'SISL_PREFIX', package('external/sisl').prefix`); with
    # autoproj's default layout every package's prefix is the same folder
    # ($AUTOPROJ_ROOT/install), so the value alone cannot say whose it is.
    # While the package sets' blocks run, each package's prefix is a folder
    # of its own (its marker); afterwards the real prefixes come back, and a
    # value read meanwhile is written either with autoproj's prefix
    # (#restore) or with a reference to the package (#references:
    # "${prefix:external/sisl}", which the release replaces with that
    # package's release prefix, Plan::DebianInputs).
    class PrefixMarkers
      # Where the markers live: below the workspace's prefix, in a folder
      # no autoproj layout makes.
      FOLDER = ".relspec-prefix-of"

      # A reference in a catalog value (name: the autoproj package).
      REFERENCE = /\$\{prefix:([^}]+)\}/

      def self.reference(name)
        "${prefix:#{name}}"
      end

      # +packages+: the Autobuild::Package objects, their prefixes set by
      # autoproj; +prefix_dir+: the workspace's prefix.
      def initialize(packages, prefix_dir:)
        @packages = packages
        @originals = packages.to_h { |pkg| [pkg.name, pkg.prefix] }
        # the longest first: one marker may start another's ("a" and "a/b")
        @markers = packages.to_h { |pkg| [pkg.name, File.join(prefix_dir, FOLDER, pkg.name)] }
                           .sort_by { |_, marker| -marker.length }.to_h
      end

      # Runs the block with each package's prefix its marker.
      def while_marked
        @packages.each { |pkg| pkg.prefix = @markers.fetch(pkg.name) }
        yield
      ensure
        @packages.each { |pkg| pkg.prefix = @originals.fetch(pkg.name) }
      end

      # +value+ with each marker written as autoproj's prefix of its package.
      def restore(value)
        replace(value) { |name| @originals.fetch(name) }
      end

      # +value+ with each marker written as a reference to its package.
      def references(value)
        replace(value) { |name| self.class.reference(name) }
      end

      private

      def replace(value)
        return value unless value.include?(FOLDER)

        @markers.reduce(value) do |text, (name, marker)|
          text.gsub(/#{Regexp.escape(marker)}(?![\w.+-])/) { yield name }
        end
      end
    end
  end
end
