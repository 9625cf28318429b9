# frozen_string_literal: true

require "find"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Debian
    # overlays/<package>/ (package name with "/" kept as folders):
    #   files/…        files copied over the source (they end up in the orig tarball)
    #   patches/*.patch quilt patches, listed in debian/patches/series in name order
    #   debian/…       files replacing the generated debian/ ones
    # In overlay files (not patches), @RELSPEC_INSTALL_DIR@, @RELSPEC_RELEASE@
    # and @RELSPEC_PACKAGE@ are replaced. Links are refused, so an overlay can
    # never reach outside its package's tree.
    class Overlay
      PLACEHOLDERS = %w[@RELSPEC_INSTALL_DIR@ @RELSPEC_RELEASE@ @RELSPEC_PACKAGE@].freeze

      def self.for(root, package_name)
        new(File.join(root, "overlays", package_name))
      end

      def initialize(dir)
        @dir = dir
      end

      def empty?
        !File.directory?(@dir)
      end

      # relative path => content, with placeholders replaced
      def files(substitutions)
        read_tree("files").transform_values { |content| substitute(content, substitutions) }
      end

      def debian_files(substitutions)
        read_tree("debian").transform_values { |content| substitute(content, substitutions) }
      end

      # [[name, content], …] in name order, each with a DEP-3 header.
      def patches(package_name)
        read_tree("patches").select { |name, _| name.end_with?(".patch") && !name.include?("/") }.sort.map do |name, content|
          [name, content.match?(/\A(Description|Subject|From):/) ? content : "Description: #{name} (relspec overlay of #{package_name})\n---\n#{content}"]
        end
      end

      # A digest of everything in the overlay, so that changing it changes
      # what is emitted.
      def signature
        %w[files patches debian].flat_map { |part| read_tree(part).sort.map { |path, content| "#{part}/#{path}\0#{content}" } }.join("\0")
      end

      private

      def read_tree(part)
        base = File.join(@dir, part)
        return {} unless File.directory?(base)

        result = {}
        Find.find(base) do |path|
          stat = File.lstat(path)
          raise InvalidInput, [problem(path, "overlays may not contain links")] if stat.symlink?
          next unless stat.file?

          relative = path.delete_prefix("#{base}/")
          raise InvalidInput, [problem(path, "overlay path escapes the package tree")] if relative.split("/").include?("..")

          result[relative] = File.binread(path)
        end
        result.sort.to_h
      end

      def substitute(content, substitutions)
        return content unless content.valid_encoding? || content.force_encoding(Encoding::UTF_8).valid_encoding?

        PLACEHOLDERS.reduce(content.dup.force_encoding(Encoding::UTF_8)) do |text, placeholder|
          text.gsub(placeholder, substitutions.fetch(placeholder, placeholder))
        end
      end

      def problem(path, message)
        Diagnostic.error("overlay", message, location: Location.file_only(path))
      end
    end
  end
end
