# frozen_string_literal: true

module Relspec
  module Osdeps
    # What the release index and the package set need of one release, read
    # from its effective spec in this one place, each value with where it
    # was written (for messages): name, parents, repository URL, whether the
    # repository is trusted, the public keyring that verifies it and its local
    # path (both nil when not given), install prefix, separate prefixes,
    # targets ({codename => [arch]}).
    IndexedRelease = Struct.new(:name, :parents, :url, :trusted, :keyring, :repository_path, :install_prefix,
                                :separate_prefixes, :targets, :locations, keyword_init: true) do
      # +spec_path+: the spec's file, which repository paths are relative to.
      def self.from_effective(spec, spec_path: nil)
        repository = spec["repository"] || {}
        path = ->(key) { repository[key] && spec_path && File.expand_path(repository[key], File.dirname(spec_path)) }
        new(name: spec.release, parents: Array(spec["parent"]), url: repository["url"]&.chomp("/"),
            trusted: repository["trusted"] == true, keyring: path.call("keyring"), repository_path: path.call("path"),
            install_prefix: spec["install_prefix"], separate_prefixes: spec["separate_prefixes"] != false,
            targets: spec.targets.to_h { |codename, archs| [codename.to_s, Array(archs).map(&:to_s)] },
            locations: %w[release parent repository install_prefix].to_h { |key| [key, spec.origin(key)&.location] })
      end

      # Where +key+ was written, else the release's own name line.
      def location(key)
        locations[key] || locations["release"]
      end
    end
  end
end
