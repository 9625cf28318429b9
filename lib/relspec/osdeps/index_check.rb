# frozen_string_literal: true

require "uri"
require_relative "../diagnostic"

module Relspec
  module Osdeps
    # What a release index (releases.yml) cannot say, found before anything
    # is written. A package set reading the index builds each release's apt
    # source as `<repo_url>/<release>`, follows one `depends_on` per release
    # and looks for packages' env.yml below /opt/rock: a release outside
    # that would give users a wrong apt line (which makes every apt command
    # fail) or silently lose packages.
    module IndexCheck
      PREFIX = "/opt/rock"

      module_function

      # +releases+: IndexedRelease of every spec; returns Diagnostics.
      def problems(releases)
        names = releases.map(&:name)
        releases.sort_by(&:name).flat_map do |release|
          url_problems(release) + parent_problems(release, names) + prefix_problems(release)
        end
      end

      def url_problems(release)
        url = release.url
        unless url && http?(url)
          text = url ? "the repository URL #{url.inspect} is not an http(s) URL" : "the release has no repository.url"
          return [Diagnostic.error("index-url", "#{text}: the release index needs where users' apt reads #{release.name}",
                                   location: release.location("repository"),
                                   hint: "add `repository: { url: https://…/#{release.name} }`")]
        end
        return [] if File.basename(URI(url).path) == release.name

        [Diagnostic.error("index-url", "the repository URL #{url.inspect} does not end in the release name " \
                                       "#{release.name.inspect}: the index can only say <repo_url>/#{release.name}",
                          location: release.location("repository"), hint: "publish the release at …/#{release.name}")]
      end

      def parent_problems(release, names)
        if release.parents.size > 1
          return [Diagnostic.error("index-parents", "#{release.name} has #{release.parents.size} parents; " \
                                                    "the release index holds one (depends_on)",
                                   location: release.location("parent"))]
        end
        external = release.parents.reject { |parent| names.include?(parent) }
        external.map do |parent|
          Diagnostic.error("index-parents", "the parent #{parent} has no spec here; the release index " \
                                            "cannot point to an external release",
                           location: release.location("parent"))
        end
      end

      def prefix_problems(release)
        return [] if release.install_prefix == PREFIX

        [Diagnostic.error("index-prefix", "install_prefix #{release.install_prefix} cannot be expressed in the " \
                                          "release index: package sets find packages' env.yml below #{PREFIX}",
                          location: release.location("install_prefix"))]
      end

      def http?(url)
        uri = URI(url)
        %w[http https].include?(uri.scheme) && !uri.host.to_s.empty?
      rescue URI::InvalidURIError
        false
      end
    end
  end
end
