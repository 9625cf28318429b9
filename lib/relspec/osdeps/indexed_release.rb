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
      # +spec+: an EffectiveSpec; its typed values resolve repository paths
      # against the spec that wrote them.
      def self.from_effective(spec)
        repository = spec.repository
        prefixes = spec.prefixes
        new(name: spec.release, parents: spec.parents, url: repository&.url&.chomp("/"),
            trusted: repository&.trusted == true, keyring: repository&.keyring, repository_path: repository&.path,
            install_prefix: prefixes.install_prefix, separate_prefixes: prefixes.separate_prefixes,
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
