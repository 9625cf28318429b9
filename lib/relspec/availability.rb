# frozen_string_literal: true

require_relative "error"
require_relative "plan"
require_relative "apt/cache"
require_relative "cache_writer"
require_relative "cache_dir"
require_relative "availability/requirements"
require_relative "availability/sources"
require_relative "availability/check"
require_relative "target"

module Relspec
  # OS dependency availability (docs/check.md): does every
  # Debian package the release's packages build- or run-depend on exist on
  # every target? Two entry points: `check` (relspec check) and `guard`, the
  # one commands that build run before doing anything (compile; build).
  module Availability
    # Raised by guard: a relation is missing on a target, or a source failed.
    class MissingDependencies < Error
      attr_reader :report

      def initialize(report)
        @report = report
        super("OS dependencies are missing on the release's targets, nothing was written:\n" \
              "#{report.text.chomp}\n(see `relspec check`; --no-check skips this check)")
      end
    end

    # `relspec check`: plans the release at +path+ and checks the targets
    # +target+ names ("codename/arch", nil: all); +launchpad_url+: the
    # Launchpad API to ask.
    def self.run(path, target:, mode:, launchpad_url:, timeout:, concurrency:)
      cache_writer = CacheWriter.new
      planned = Plan.run(path, timeout: timeout, cache_writer: cache_writer)
      only = Target.select(target, planned.plan.targets.keys, planned.plan.release)
      check(planned, mode: mode, launchpad: LaunchpadClient.new(base: launchpad_url, timeout: timeout), only: only,
                     timeout: timeout, concurrency: concurrency, cache_writer: cache_writer)
    end

    # The check of a planned release (+planned+: Plan::Result). +mode+:
    # auto, apt or launchpad (Sources); +launchpad+: a LaunchpadClient, nil
    # to take Launchpad answers from the cache only; +only+: targets to check.
    # +launchpad_base+: whose cached answers count when +launchpad+ is nil.
    # +cache_writer+: the CacheWriter of the run's caches (planning's too).
    def self.check(planned, mode: "auto", launchpad: nil, only: nil, timeout: 10,
                   concurrency: LaunchpadSource::CONCURRENCY, launchpad_base: nil, cache_writer: CacheWriter.new)
      launchpad_base = launchpad&.base || launchpad_base || LaunchpadClient::DEFAULT_BASE
      sources = Sources.new(planned.effective.distributions, mode: mode, spec_dir: planned.spec_dir,
                                                             launchpad: launchpad, fetcher_options: { timeout: timeout },
                                                             apt_cache: Apt::Cache.new(Apt::Cache.default_dir, writer: cache_writer),
                                                             names_cache: Apt::Cache.new(CacheDir.for("availability"),
                                                                                         writer: cache_writer),
                                                             answer_cache: AnswerCache.new(AnswerCache.default_dir,
                                                                                           writer: cache_writer),
                                                             concurrency: concurrency, launchpad_base: launchpad_base)
      Check.run(planned.effective.release, Requirements.of(planned, only: only), sources)
    end

    # The same check from what is at hand: apt archives as configured (their
    # indices cached by checksum), Launchpad only from its answer cache, never
    # asking the network. Returns the Report (its #unchecked targets deserve
    # a note); raises MissingDependencies when the release must not be built.
    def self.guard(planned, timeout: 10, launchpad_base: LaunchpadClient::DEFAULT_BASE, cache_writer: CacheWriter.new)
      report = check(planned, timeout: timeout, launchpad_base: launchpad_base, cache_writer: cache_writer)
      raise MissingDependencies, report if report.failed?

      report
    end
  end
end
