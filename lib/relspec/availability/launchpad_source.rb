# frozen_string_literal: true

require_relative "launchpad_client"
require_relative "answer_cache"
require_relative "hint"
require_relative "../worker_pool"

module Relspec
  module Availability
    # Availability of Ubuntu targets from Launchpad: one question per
    # distinct (name, series, architecture), asked concurrently (at most
    # +concurrency+ at a time) and only when the AnswerCache has no fresh
    # answer. Without a client it answers from the cache alone (what compile
    # does: it never goes to the network for this), leaving the rest unknown.
    class LaunchpadSource
      CONCURRENCY = 4

      # Launchpad's publishing records carry no Provides field. The one
      # virtual package relspec's own debian/control templates use is
      # asked for through the package that provides it.
      VIRTUAL = { "debhelper-compat" => "debhelper" }.freeze

      def initialize(client:, cache:, base: client&.base || LaunchpadClient::DEFAULT_BASE, concurrency: CONCURRENCY)
        @client = client
        @cache = cache
        @base = base
        @concurrency = [concurrency.to_i, 1].max
      end

      def describe
        @client ? "launchpad: #{@base}" : "launchpad: cached answers of #{@base}"
      end

      # {target => [{name => true/false/nil}, problem or nil]}: nil answers
      # are unknown (not cached, or the series could not be asked).
      def lookup_many(wanted)
        questions = wanted.flat_map { |target, names| names.map { |name| question(target, name) } }.uniq
        answers = questions.to_h { |key| [key, @cache.read(cache_key(key))] }
        problems = {}
        ask(answers.select { |_, found| found.nil? }.keys, answers, problems) if @client
        wanted.to_h do |target, names|
          found = names.to_h { |name| [name, answers[question(target, name)]] }
          [target, [found, problems[[target.codename, target.arch]]]]
        end
      end

      # A name Launchpad does publish there that looks like +name+ (one more
      # question, by substring); nil without a client or when none is close.
      def hint(target, name)
        stem = stem_of(name)
        return nil unless @client && stem.size >= Hint::PREFIX

        entries = @client.published_binaries(stem, target.codename, target.arch, exact: false)
        Hint.new(entries.map { |entry| entry["binary_package_name"] }.compact.uniq - [name]).for(name)
      rescue LaunchpadClient::Failure
        nil
      end

      private

      # What similar names share: the part before the first digit (the
      # version), else the name without its last part (-dev, -common).
      def stem_of(name)
        digit = name.index(/\d/)
        (digit ? name[0...digit] : name.sub(/-[^-]+\z/, "")).chomp("-")
      end

      def question(target, name)
        [VIRTUAL.fetch(name, name), target.codename, target.arch]
      end

      def cache_key(question)
        [@base, *question].join("\n")
      end

      # Runs the questions on a few threads; a series Launchpad does not know
      # is asked once, not once per name.
      def ask(questions, answers, problems)
        lock = Mutex.new
        WorkerPool.new(@concurrency).each(questions) { |item| settle(item, answers, problems, lock) }
      end

      def settle(item, answers, problems, lock)
        series = item.drop(1)
        return if lock.synchronize { problems.key?(series) }

        found = answer(item)
        lock.synchronize { answers[item] = found }
      rescue LaunchpadClient::Failure => e
        lock.synchronize { problems[series] ||= e.message }
      end

      def answer(item)
        name, series, arch = item
        found = @client.published_binaries(name, series, arch).any? { |entry| entry["binary_package_name"] == name }
        @cache.write(cache_key(item), found)
        found
      end
    end
  end
end
