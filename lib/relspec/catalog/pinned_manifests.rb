# frozen_string_literal: true

require "open3"
require_relative "git_state"

module Relspec
  class Catalog
    # A pinned package is built from the pinned commit, so its dependencies
    # are those of that commit's manifest.xml, not of the checkout's working
    # tree (an old tag of base/cmake does not depend on pkg-config yet). This
    # reads the manifest of each pinned commit from git (`git show
    # <commit>:manifest.xml`; the working tree is never touched) where it
    # differs from the checkout's, for autoproj to load instead.
    module PinnedManifests
      # What a commit without manifest.xml declares: nothing.
      EMPTY = "<package/>\n"

      module_function

      # +pins+: name => ReleaseSpec::Pin; +root+: the
      # workspace. Returns name => manifest.xml text. A pin the checkout
      # does not have is left to Pinning, which reports it.
      def of(catalog, pins, root)
        pins.sort.each_with_object({}) do |(name, pin), manifests|
          next unless catalog.package?(name)

          package = catalog.package(name)
          next unless package.checked_out && package.source_dir

          text = at_pin(File.join(root, package.source_dir), pin)
          manifests[name] = text if text && text != current(File.join(root, package.source_dir))
        end
      end

      def at_pin(dir, pin)
        commit, = GitState.resolve(dir, pin.ref, pin.value.to_s)
        return nil unless commit

        text, status = Open3.capture2("git", "-C", dir, "show", "#{commit}:manifest.xml", err: File::NULL)
        status.success? ? text : EMPTY
      end

      def current(dir)
        path = File.join(dir, "manifest.xml")
        File.file?(path) ? File.read(path) : EMPTY
      end
    end
  end
end
