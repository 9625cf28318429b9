# frozen_string_literal: true

module Relspec
  class Catalog
    # A patch a package set applies to a package when autoproj imports it
    # (the VCS entry's `patches:`), as autobuild applies it: `patch
    # -p<level> --forward` in the package's source folder, in list order.
    # +path+ is where the package set keeps it (relative to the workspace),
    # +content+ its text: the catalog carries the text so that a snapshot
    # compiles the same source package as the workspace.
    ImportPatch = Struct.new(:path, :level, :content, keyword_init: true) do
      def self.from_h(hash)
        new(path: hash.fetch("path"), level: Integer(hash.fetch("level", 0)), content: hash.fetch("content")).freeze
      end

      # The patches of an autobuild importer as it applies them
      # (Importer#patches: each with its level and the file's text), as
      # hashes; +relative+ turns a file's path into the catalog's.
      def self.list_of(importer, &relative)
        return [] unless importer.respond_to?(:patches)

        importer.patches.map do |path, level, content|
          { "path" => relative.call(path), "level" => Integer(level), "content" => content }
        end
      end

      def to_h
        { "path" => path, "level" => level, "content" => content }
      end
    end
  end
end
