# frozen_string_literal: true

require "digest"
require_relative "../cache_dir"
require_relative "../cache_writer"

module Relspec
  module Availability
    # Launchpad's answers (does this name exist on series/arch?) kept for a
    # while: a name that exists stays so for a day, a missing one is asked
    # again after an hour (it may just have been published). Transient
    # failures are never stored. One small file per question, written
    # atomically, so concurrent lookups and runs never see half an answer.
    class AnswerCache
      FOUND_TTL = 24 * 3600
      MISSING_TTL = 3600

      def self.default_dir
        CacheDir.for("launchpad")
      end

      # +dir+ nil: nothing is kept. +clock+ gives the current epoch seconds;
      # +writer+: the CacheWriter the run's caches share.
      def initialize(dir, found_ttl: FOUND_TTL, missing_ttl: MISSING_TTL, clock: -> { Time.now.to_i },
                     writer: CacheWriter.new)
        @dir = dir
        @writer = writer
        @found_ttl = found_ttl
        @missing_ttl = missing_ttl
        @clock = clock
      end

      # true/false while fresh, nil when unknown or expired.
      def read(key)
        return nil unless @dir

        state, stamp = File.read(location(key)).split
        found = state == "found"
        age = @clock.call - Integer(stamp, 10)
        if age >= 0 && age < (found ? @found_ttl : @missing_ttl)
          found
        end
      rescue SystemCallError, ArgumentError, TypeError
        nil
      end

      def write(key, found)
        return unless @dir

        @writer.write(location(key), "#{found ? 'found' : 'missing'} #{@clock.call}\n")
      end

      private

      def location(key)
        digest = Digest::SHA256.hexdigest(key)
        File.join(@dir, digest[0, 2], digest)
      end
    end
  end
end
