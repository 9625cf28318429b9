# frozen_string_literal: true

require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Debian
    # A package set's import patch (Catalog::ImportPatch) as a quilt patch
    # of the source package. autobuild applies it with `patch -p<level>` in
    # the source folder; dpkg-source applies debian/patches with -p1. So
    # the file names of each `---`/`+++` header are stripped of +level+
    # components, as patch strips them, and written as a/<path>, b/<path>;
    # the hunks are kept byte for byte. The .orig stays the upstream tree
    # and the patch is visible in debian/patches, first in the series, since
    # autoproj applies it at import, before anything else changes the tree.
    module PackageSetPatch
      HUNK = /\A@@ -\d+(?:,(\d+))? \+\d+(?:,(\d+))? @@/

      module_function

      # [series name, patch text] for the +index+-th (0-based) patch of
      # +package_name+. +exists+: whether a relative path is a file of the
      # upstream tree (patch picks the name that exists when old and new
      # differ, as rock.core's `--- ../class_loader/x` `+++ ./x` do).
      def of(patch, index:, package_name:, exists:)
        name = format("autoproj-%<n>02d-%<base>s", n: index + 1, base: series_base(patch.path))
        header = "Description: #{patch.path} (package set patch of #{package_name}, applied by autoproj " \
                 "with patch -p#{patch.level})\nForwarded: not-needed\n---\n"
        [name, header.b + rewrite(patch, exists).b]
      end

      # A name debian/patches/series can carry (Overlay::PATCH_NAME).
      def series_base(path)
        base = File.basename(path).gsub(/[^A-Za-z0-9._+~=-]/, "_").sub(/\A[^A-Za-z0-9]+/, "")
        base.end_with?(".patch") ? base : "#{base}.patch"
      end

      def rewrite(patch, exists)
        lines = patch.content.b.lines
        out = []
        index = 0
        while index < lines.size
          line = lines[index]
          if line.start_with?("--- ") && lines[index + 1]&.start_with?("+++ ")
            out.concat(headers(line, lines[index + 1], patch, exists))
            index += 2
          elsif (hunk = line.match(HUNK))
            length = 1 + hunk_length(lines, index, hunk)
            out.concat(lines[index, length])
            index += length
          else
            out << line
            index += 1
          end
        end
        out.join
      end

      # The lines of the hunk starting at +start+ (after its @@ line).
      def hunk_length(lines, start, hunk)
        old = (hunk[1] || "1").to_i
        new = (hunk[2] || "1").to_i
        count = 0
        while (old.positive? || new.positive?) && (line = lines[start + 1 + count])
          case line[0]
          when " ", "\n" then old -= 1
                              new -= 1
          when "-" then old -= 1
          when "+" then new -= 1
          end
          count += 1
        end
        count += 1 if lines[start + 1 + count]&.start_with?("\\")
        count
      end

      def headers(old_line, new_line, patch, exists)
        old = stripped(header_name(old_line), patch)
        new = stripped(header_name(new_line), patch)
        # patch refuses names that leave the folder, and takes the one that exists
        safe = [new, old].compact.reject { |path| path.split("/").include?("..") }
        refuse(patch, "names no file inside the package's folder (#{old_line.strip})") if safe.empty?
        target = safe.find { |path| exists.call(path) } || safe.first
        missing!(patch, [old, new].compact.uniq) if old && !exists.call(target)
        ["--- #{old ? "a/#{target}" : '/dev/null'}\n", "+++ #{new ? "b/#{target}" : '/dev/null'}\n"]
      end

      def header_name(line)
        line.chomp.delete_prefix(line[0, 4]).sub(/\t.*\z/, "")
      end

      # The path patch -p<level> uses, without "." components; nil for /dev/null.
      def stripped(name, patch)
        return nil if name == "/dev/null"

        parts = name.split("/").reject(&:empty?).drop(patch.level).reject { |part| part == "." }
        refuse(patch, "names #{name}, which has fewer than #{patch.level + 1} path components") if parts.empty?
        parts.join("/")
      end

      # A file the patch changes that the tree does not have at the patch's
      # level: dpkg-source would stop at "can't find file to patch" (a
      # patch made with `diff -ru a/ b/` needs level 1, autobuild's default
      # is 0). A file created by the patch (--- /dev/null) is not looked for.
      def missing!(patch, names)
        refuse(patch, "changes #{names.join(' or ')}, which the package's source does not have at level " \
                      "#{patch.level} (patch -p#{patch.level})",
               hint: "fix the patch's file names, or its level in the package set (`patches: [[file, level]]`; " \
                     "autobuild's default level is 0, a patch made by `diff -ru a/ b/` needs 1)")
      end

      def refuse(patch, problem, hint: "fix the patch or its level in the package set")
        raise InvalidInput, [Diagnostic.error("package-set-patch", "package set patch #{patch.path} #{problem}",
                                              location: Location.file_only(patch.path), hint: hint)]
      end
    end
  end
end
