# frozen_string_literal: true

require_relative "../apt/opening"
require_relative "../apt/cache"
require_relative "../cache_dir"
require_relative "apt_source"
require_relative "launchpad_source"

module Relspec
  module Availability
    # Which source answers for which target (`--source`):
    # - apt: the distribution's `archive` (a repository, or `host: true`
    #   for this machine's apt lists);
    # - launchpad: Launchpad, for Ubuntu targets;
    # - auto: the archive where one is configured, else Launchpad for Ubuntu.
    # A target no source can answer for is left unchecked, with the reason.
    class Sources
      MODES = %w[auto apt launchpad].freeze

      # +launchpad+: a LaunchpadClient, or nil to use cached answers only.
      def initialize(distributions, mode:, spec_dir:, launchpad:, fetcher_options: {}, apt_cache: Apt::Cache.new(nil),
                     names_cache: Apt::Cache.new(CacheDir.for("availability")),
                     answer_cache: AnswerCache.new(AnswerCache.default_dir), concurrency: LaunchpadSource::CONCURRENCY,
                     launchpad_base: launchpad&.base || LaunchpadClient::DEFAULT_BASE)
        raise ArgumentError, "unknown source #{mode.inspect} (#{MODES.join(', ')})" unless MODES.include?(mode)

        @distributions = distributions
        @mode = mode
        @spec_dir = spec_dir
        @fetcher_options = fetcher_options
        @apt_cache = apt_cache
        @names_cache = names_cache
        @launchpad = LaunchpadSource.new(client: launchpad, cache: answer_cache, base: launchpad_base,
                                         concurrency: concurrency)
        @archives = {}
      end

      # [source, nil] or [nil, why there is none].
      def for(target)
        distribution = @distributions.fetch(target.codename)
        archive = distribution.archive
        return [archive_source(target.codename, archive), nil] if archive && @mode != "launchpad"
        return [@launchpad, nil] if distribution.type == "ubuntu" && @mode != "apt"

        [nil, no_source(distribution)]
      end

      private

      def archive_source(codename, archive)
        @archives[codename] ||= AptSource.new(
          Apt::Opening.archive(archive, @spec_dir, fetcher_options: @fetcher_options, cache: @apt_cache),
          archive.read_components, names_cache: @names_cache
        )
      end

      def no_source(distribution)
        codename = distribution.codename
        case @mode
        when "launchpad" then "Launchpad has Ubuntu only (#{codename} is #{distribution.type})"
        else "no archive configured (set distributions.#{codename}.archive, or host: true for this machine's apt lists)"
        end
      end
    end
  end
end
