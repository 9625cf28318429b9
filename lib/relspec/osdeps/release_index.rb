# frozen_string_literal: true

require_relative "../yaml/writer"

module Relspec
  module Osdeps
    # releases.yml of the rock-osdeps package set: a `default:` entry (where
    # releases live, their signing key, the prefix layout) and one entry per
    # release saying what differs: `depends_on` its parent, `separate_prefixes`,
    # `repo_url` when the release is not published below the default URL.
    module ReleaseIndex
      module_function

      # +releases+: EffectiveSpec of every release in specs/, +repo_url+ and
      # +public_key+: the defaults (repo_url defaults to the folder most
      # release URLs share).
      def render(releases, repo_url: nil, public_key: nil)
        repo_url ||= common_base(releases)
        separate = majority(releases.map { |spec| spec.prefixes.separate_prefixes })
        index = { "default" => { "repo_url" => repo_url, "public_key" => public_key,
                                 "separate_prefixes" => separate }.compact }
        releases.sort_by(&:release).each do |spec|
          index[spec.release] = entry(spec, repo_url, separate)
        end
        Yaml::Writer.dump(index)
      end

      def entry(spec, repo_url, separate)
        entry = {}
        parent = spec.parents.first
        entry["depends_on"] = parent if parent
        entry["separate_prefixes"] = spec.prefixes.separate_prefixes if spec.prefixes.separate_prefixes != separate
        url = release_url(spec)
        entry["repo_url"] = File.dirname(url) if url && repo_url && File.dirname(url) != repo_url
        entry.empty? ? nil : entry
      end

      def release_url(spec)
        spec.repository&.url&.chomp("/")
      end

      def common_base(releases)
        bases = releases.filter_map { |spec| release_url(spec) && File.dirname(release_url(spec)) }
        bases.tally.max_by { |base, count| [count, base] }&.first
      end

      def majority(values)
        values.count(true) >= values.count(false)
      end
    end
  end
end
