# frozen_string_literal: true

require_relative "../yaml/writer"
require_relative "../error"
require_relative "index_check"
require_relative "indexed_release"

module Relspec
  module Osdeps
    # releases.yml of the rock-osdeps package set: a `default:` entry (where
    # releases live, their signing key, the prefix layout) and one entry per
    # release saying what differs: `depends_on` its parent, `separate_prefixes`,
    # `repo_url` when the release is not published below the default URL.
    module ReleaseIndex
      module_function

      # +releases+: IndexedRelease of every release in specs/, +repo_url+
      # and +public_key+: the defaults (repo_url defaults to the folder most
      # release URLs share). Raises InvalidInput for a release the index
      # cannot express (IndexCheck).
      def render(releases, repo_url: nil, public_key: nil)
        problems = IndexCheck.problems(releases)
        raise InvalidInput, problems unless problems.empty?

        repo_url = repo_url&.chomp("/") || common_base(releases)
        separate = majority(releases.map(&:separate_prefixes))
        index = { "default" => { "repo_url" => repo_url, "public_key" => public_key,
                                 "separate_prefixes" => separate }.compact }
        releases.sort_by(&:name).each do |release|
          index[release.name] = entry(release, repo_url, separate)
        end
        Yaml::Writer.dump(index)
      end

      def entry(release, repo_url, separate)
        entry = {}
        entry["depends_on"] = release.parents.first unless release.parents.empty?
        entry["separate_prefixes"] = release.separate_prefixes if release.separate_prefixes != separate
        base = File.dirname(release.url)
        entry["repo_url"] = base if base != repo_url
        entry.empty? ? nil : entry
      end

      def common_base(releases)
        releases.map { |release| File.dirname(release.url) }.tally.max_by { |base, count| [count, base] }&.first
      end

      def majority(values)
        values.count(true) >= values.count(false)
      end
    end
  end
end
