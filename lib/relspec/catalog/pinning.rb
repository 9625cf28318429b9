# frozen_string_literal: true

require_relative "../catalog"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../suggestion"
require_relative "git_state"

module Relspec
  class Catalog
    # Applies a spec's pins to a catalog: a pinned package's source is the
    # pinned commit, tag or branch instead of what the workspace follows.
    #
    # With a workspace at hand the pin is resolved in the package's checkout
    # (offline): the commit it names and that commit's time, which the
    # upstream version is made of. A pin the checkout does not have is an
    # error. From a snapshot, a commit pin is taken as written and its time
    # stays unknown.
    class Pinning
      # +pins+: package => ReleaseSpec::Pin; +root+: the
      # workspace root, or nil for a snapshot; +locate+: name => Location of
      # the pin, for messages.
      def self.apply(catalog, pins, root:, locate: ->(_name) {})
        new(catalog, pins, root, locate).apply
      end

      def initialize(catalog, pins, root, locate)
        @catalog = catalog
        @pins = pins
        @root = root
        @locate = locate
        @problems = []
      end

      def apply
        packages = @catalog.packages.to_h do |name, package|
          pin = @pins[name]
          [name, pin ? pinned(package, pin) : package]
        end
        @pins.each_key { |name| unknown(name) unless @catalog.package?(name) }
        raise InvalidInput, @problems unless @problems.empty?

        @catalog.with_packages(packages)
      end

      private

      def pinned(package, pin)
        ref = pin.ref
        value = pin.value
        vcs = package.vcs.pinned(pin.to_h)
        return from_snapshot(package, vcs, ref, value) if @root.nil?

        commit, time = GitState.resolve(File.join(@root, package.source_dir), ref, value)
        unless commit
          problem("pin-not-found", package.name, "pinned #{ref} #{value} of #{package.name} is not in its checkout #{package.source_dir}",
                  "fetch it into the checkout (autoproj update, or git fetch in #{package.source_dir}), or fix the pin")
          return package
        end
        package.with(vcs: vcs.pinned("commit" => commit), commit_time: time)
      end

      # Without checkouts only a pin on the commit the snapshot recorded keeps
      # its commit time.
      def from_snapshot(package, vcs, ref, value)
        current = package.vcs.commit
        if ref == "commit" && current&.start_with?(value)
          package.with(vcs: vcs.pinned("commit" => current))
        elsif ref == "commit"
          package.with(vcs: vcs.pinned("commit" => value), commit_time: nil)
        else
          package.with(vcs: vcs, commit_time: nil)
        end
      end

      def unknown(name)
        problem("unknown-package", name, "pin names #{name.inspect}, which is not a package of the workspace",
                Suggestion.hint(name, @catalog.packages.keys))
      end

      def problem(rule, name, message, hint)
        @problems << Diagnostic.error(rule, message, location: @locate.call(name) || Location.file_only("pins"), hint: hint)
      end
    end
  end
end
