# frozen_string_literal: true

require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Debian
    # The files/ of an overlay as one quilt patch (docs/design.md, One truth for versions): the orig
    # tarball of an upstream version stays the upstream tree byte for byte,
    # and what the overlay changes travels in debian/patches like any other
    # Debian change. Each file becomes one hunk replacing the upstream file
    # whole (or creating it): not the smallest diff, but exact, and made
    # without an external tool.
    module OverlayPatch
      NAME = "relspec-overlay-files.patch"

      module_function

      # +files+: relative path => new content; +upstream+: a callable giving
      # the upstream content of a path (nil when upstream has no such file).
      # Returns the patch text, or nil when nothing differs.
      def of(files, upstream:, package_name:, overlay_dir:)
        hunks = files.sort.filter_map do |path, content|
          check(path, content, overlay_dir)
          old = upstream.call(path)
          next if old == content

          file_diff(path, old, content)
        end
        return nil if hunks.empty?

        "Description: files of overlays/#{package_name}/files over the upstream tree\n" \
        "Forwarded: not-needed\n---\n".b + hunks.join.b
      end

      def file_diff(path, old, new)
        old_lines = lines(old)
        new_lines = lines(new)
        text = "--- #{old ? "a/#{path}" : '/dev/null'}\n+++ b/#{path}\n".b
        text << "@@ -#{range(old_lines)} +#{range(new_lines)} @@\n".b
        text << body(old_lines, "-") << body(new_lines, "+")
      end

      def lines(text)
        return [] if text.nil? || text.empty?

        text.b.lines
      end

      def range(lines)
        lines.empty? ? "0,0" : "1,#{lines.size}"
      end

      def body(lines, sign)
        lines.map do |line|
          line.end_with?("\n") ? sign.b + line : sign.b + line + "\n\\ No newline at end of file\n".b
        end.join.b
      end

      # What a text patch cannot carry.
      def check(path, content, overlay_dir)
        problem = if content.b.include?("\0") then "is binary"
                  elsif content.empty? then "is empty"
                  end
        return unless problem

        raise InvalidInput, [Diagnostic.error("overlay", "overlay file #{path} #{problem}: overlay files travel as a " \
                                                         "text patch in debian/patches",
                                              location: Location.file_only(File.join(overlay_dir, "files", path)),
                                              hint: "put the file under the overlay's debian/ and install it from there")]
      end
    end
  end
end
