# frozen_string_literal: true

module Relspec
  module Osdeps
    # What the release index needs of one release, read from its effective
    # spec in this one place, each value with where it was written (for
    # messages): name, parents, repository URL and whether the repository is
    # trusted, install prefix, separate prefixes.
    IndexedRelease = Struct.new(:name, :parents, :url, :trusted, :install_prefix, :separate_prefixes, :locations,
                                keyword_init: true) do
      def self.from_effective(spec)
        repository = spec["repository"] || {}
        new(name: spec.release, parents: Array(spec["parent"]), url: repository["url"]&.chomp("/"),
            trusted: repository["trusted"] == true, install_prefix: spec["install_prefix"],
            separate_prefixes: spec["separate_prefixes"] != false,
            locations: %w[release parent repository install_prefix].to_h { |key| [key, spec.origin(key)&.location] })
      end

      # Where +key+ was written, else the release's own name line.
      def location(key)
        locations[key] || locations["release"]
      end
    end
  end
end
