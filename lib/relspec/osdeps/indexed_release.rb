# frozen_string_literal: true

module Relspec
  module Osdeps
    # What the release index and the package set need of one release, read
    # from its effective spec in this one place, each value with where it
    # was written (for messages): name, parents, repository URL, whether the
    # repository is trusted and which key signs it, its local path (nil when
    # not given), install prefix, separate prefixes, targets
    # ({codename => [arch]}).
    IndexedRelease = Struct.new(:name, :parents, :url, :trusted, :sign_with, :repository_path, :install_prefix,
                                :separate_prefixes, :targets, :locations, keyword_init: true) do
      # +spec_path+: the spec's file, which repository.path is relative to.
      def self.from_effective(spec, spec_path: nil)
        repository = spec["repository"] || {}
        path = repository["path"] && spec_path && File.expand_path(repository["path"], File.dirname(spec_path))
        new(name: spec.release, parents: Array(spec["parent"]), url: repository["url"]&.chomp("/"),
            trusted: repository["trusted"] == true, sign_with: repository["sign_with"], repository_path: path,
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
