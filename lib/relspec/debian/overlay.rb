# frozen_string_literal: true

require "find"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../printable"

module Relspec
  module Debian
    # overlays/<package>/ (package name with "/" kept as folders):
    #   files/…        files over the source, carried as one generated quilt patch
    #                  (the orig tarball stays the upstream tree: OverlayPatch)
    #   patches/*.patch quilt patches, listed in debian/patches/series in name order
    #   debian/…       files replacing the generated debian/ ones
    #   @<codename>/patches, @<codename>/debian   the same for one
    #                  distribution only (an upstream incompatibility with its
    #                  toolchain), over the common ones
    #   @<arch>/patches, @<arch>/debian   the same for one architecture only,
    #                  over those (files/ cannot be per codename or
    #                  architecture: the orig tarball is the same for every
    #                  target)
    # In overlay files (not patches), @RELSPEC_INSTALL_DIR@, @RELSPEC_RELEASE@
    # and @RELSPEC_PACKAGE@ are replaced. Links are refused, so an overlay can
    # never reach outside its package's tree.
    class Overlay
      PLACEHOLDERS = %w[@RELSPEC_INSTALL_DIR@ @RELSPEC_RELEASE@ @RELSPEC_PACKAGE@].freeze

      attr_reader :dir

      # A patch name quilt's series file can carry: one token per line, no
      # comment sign, nothing that reads as an option.
      PATCH_NAME = /\A[A-Za-z0-9][A-Za-z0-9._+~=-]*\.patch\z/

      def self.for(root, package_name, arch: nil, codename: nil)
        refuse_linked_folders(root, package_name)
        new(File.join(root, "overlays", package_name), arch, codename: codename)
      end

      # overlays/<package> (each of its folders) must be a real folder of the
      # project: a link there would carry files from anywhere into the package.
      def self.refuse_linked_folders(root, package_name)
        package_name.split("/").reduce(File.join(root, "overlays")) do |path, part|
          path = File.join(path, part)
          stat = File.lstat(path)
          if stat.symlink?
            message = "overlays/#{package_name} is a link (to #{File.readlink(path)}); an overlay must be a folder of the project"
            raise InvalidInput, [Diagnostic.error("overlay", message, location: Location.file_only(path))]
          end
          return unless stat.directory?

          path
        rescue Errno::ENOENT, Errno::ENOTDIR
          return
        end
      end
      private_class_method :refuse_linked_folders

      # +codename+, +arch+: the target's; their layers (@<codename>/,
      # @<arch>/) go over the common one in that order.
      def initialize(dir, arch = nil, codename: nil)
        @dir = dir
        @arch = arch
        @layers = [codename && ["@#{codename}", "distribution"], arch && ["@#{arch}", "architecture"]].compact.freeze
        @layers.each do |layer, what|
          files = File.join(dir, layer, "files")
          next unless File.directory?(files)

          raise InvalidInput, [problem(files, "files/ cannot be per #{what} (use a patch in #{layer}/patches/)")]
        end
      end

      def empty?
        !File.directory?(@dir)
      end

      # relative path => content, with placeholders replaced
      def files(substitutions)
        read_tree("files").transform_values { |content| substitute(content, substitutions) }
      end

      def debian_files(substitutions)
        layered("debian").transform_values { |content| substitute(content, substitutions) }
      end

      # [[name, content], …] in name order, each with a DEP-3 header.
      def patches(package_name)
        found = layered("patches").select { |name, _| name.end_with?(".patch") && !name.include?("/") }
        found.each_key { |name| check_patch_name(name) }
        found.sort.map do |name, content|
          [name, content.match?(/\A(Description|Subject|From):/) ? content : "Description: #{name} (relspec overlay of #{package_name})\n---\n#{content}"]
        end
      end

      # A digest of everything in the overlay, so that changing it changes
      # what is emitted.
      def signature
        parts = %w[files patches debian].map { |part| [part, read_tree(part)] }
        parts += @layers.flat_map { |layer, _| %w[patches debian].map { |part| ["#{layer}/#{part}", read_tree("#{layer}/#{part}")] } }
        parts.flat_map { |part, tree| tree.sort.map { |path, content| "#{part}/#{path}\0#{content}" } }.join("\0")
      end

      private

      # The common part with the distribution's, then the architecture's, over it.
      def layered(part)
        @layers.reduce(read_tree(part)) { |tree, (layer, _)| tree.merge(read_tree("#{layer}/#{part}")) }.sort.to_h
      end

      def read_tree(part)
        base = File.join(@dir, part)
        return {} unless File.directory?(base)

        result = {}
        Find.find(base) do |path|
          # the name goes into debian/patches/series, a patch and messages, all UTF-8
          raise InvalidInput, [problem(Printable.text(path), "the file name is not UTF-8; rename it")] unless path.valid_encoding?

          stat = File.lstat(path)
          raise InvalidInput, [problem(path, "overlays may not contain links")] if stat.symlink?
          next unless stat.file?

          relative = path.delete_prefix("#{base}/")
          raise InvalidInput, [problem(path, "overlay path escapes the package tree")] if relative.split("/").include?("..")

          result[relative] = File.binread(path)
        end
        result.sort.to_h
      end

      def check_patch_name(name)
        return if PATCH_NAME.match?(name)

        raise InvalidInput, [Diagnostic.error("overlay", "patch name #{name.inspect} cannot be listed in debian/patches/series",
                                              location: Location.file_only(patch_path(name)),
                                              hint: "rename it with letters, digits and . _ + ~ = - only " \
                                                    "(no spaces, newlines or #), e.g. 01-fix-build.patch")]
      end

      # the file a patch name came from: the last layer that has it
      def patch_path(name)
        layer = @layers.reverse.map(&:first).find { |dir| File.exist?(File.join(@dir, dir, "patches", name)) }
        layer ? File.join(@dir, layer, "patches", name) : File.join(@dir, "patches", name)
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
