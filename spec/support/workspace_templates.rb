# frozen_string_literal: true

require "fileutils"
require "tmpdir"

class WorkspaceBuilder
  # Workspaces made once per test process, by definition: the demo
  # workspace alone is made by a dozen fixtures, each time with ~60 git
  # commands. A workspace is then a copy of its template (the same
  # commits, byte for byte) whose checkouts are clones of its own
  # repositories, as if it had been made in place.
  module Templates
    @made = {}

    class << self
      # The workspace root of the template for +definition+; the block
      # makes it in the (empty) folder it is given.
      def fetch(definition)
        key = definition.inspect
        @made[key] ||= yield(File.join(folder, @made.size.to_s))
      end

      def copy(template, root)
        FileUtils.mkdir_p(File.dirname(root))
        system("cp", "-a", template, root, exception: true)
        # a clone records the absolute path it was cloned from
        Dir.glob(File.join(root, "src", "**", ".git", "config")).each do |config|
          File.write(config, File.read(config).gsub("#{template}/", "#{root}/"))
        end
      end

      private

      def folder
        @folder ||= Dir.mktmpdir("relspec-test-workspaces").tap { |dir| at_exit { FileUtils.rm_rf(dir) } }
      end
    end
  end
end
