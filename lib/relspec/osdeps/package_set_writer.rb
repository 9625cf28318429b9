# frozen_string_literal: true

require "fileutils"

module Relspec
  module Osdeps
    # Puts a package set ({relative path => content}) into a folder as a
    # whole: it is written beside the folder and renamed over it, so the
    # folder holds either the previous package set or the new one, never a
    # mix. A folder that already holds exactly these files is left alone.
    module PackageSetWriter
      module_function

      # Returns true when the folder changed.
      def write(dir, files)
        return false if current?(dir, files)

        fresh = "#{dir}.new-#{Process.pid}"
        FileUtils.rm_rf(fresh)
        files.each do |path, content|
          target = File.join(fresh, path)
          FileUtils.mkdir_p(File.dirname(target))
          File.binwrite(target, content)
        end
        swap(fresh, dir)
        true
      ensure
        FileUtils.rm_rf(fresh) if fresh
      end

      def current?(dir, files)
        return false unless File.directory?(dir)

        present = Dir.glob("**/*", File::FNM_DOTMATCH, base: dir).reject { |path| File.directory?(File.join(dir, path)) }
        present.sort == files.keys.sort && files.all? { |path, content| File.binread(File.join(dir, path)) == content }
      end

      def swap(fresh, dir)
        FileUtils.mkdir_p(File.dirname(dir))
        old = "#{dir}.old-#{Process.pid}"
        File.rename(dir, old) if File.exist?(dir)
        File.rename(fresh, dir)
        FileUtils.rm_rf(old)
      end
    end
  end
end
