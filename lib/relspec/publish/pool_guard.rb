# frozen_string_literal: true

require "digest"
require_relative "../error"

module Relspec
  module Publish
    # A repository must never receive two different files under one name
    # (docs/design.md, One truth for versions): apt clients that saw the first would fail their checksum
    # on the second. reprepro refuses too, but only in the middle of a batch;
    # this check refuses the whole publication before anything is included,
    # and names both files. A file in pool/ that the database does not hold
    # was never published: it is what a reprepro killed while copying left
    # (often empty), and it is removed rather than compared (reprepro would
    # refuse to put the right bytes in its place).
    module PoolGuard
      module_function

      # +items+: Upload::Item; +published+: the pool paths the database
      # holds (Reprepro::Runner#pool_files). Raises PublishError on conflicts.
      def check(repository, items, published:)
        published = published.to_h { |path| [path, true] }
        digests = Hash.new { |hash, path| hash[path] = Digest::SHA256.file(path).hexdigest }
        conflicts = items.group_by(&:pool).flat_map do |pool, same|
          held = File.join(repository, pool)
          first = same.first
          within = same.reject { |item| digests[item.local] == digests[first.local] }.map do |item|
            "#{item.local} (sha256 #{digests[item.local]}) differs from #{first.local} (sha256 #{digests[first.local]}), " \
              "both to be published as #{pool}"
          end
          next within unless File.file?(held)

          unless published[pool]
            File.unlink(held) # an interrupted reprepro's leftover, never published
            next within
          end

          within + same.reject { |item| digests[item.local] == digests[held] }.map do |item|
            "#{item.local} (sha256 #{digests[item.local]}) differs from #{held} (sha256 #{digests[held]}), already published"
          end
        end
        return if conflicts.empty?

        raise PublishError, "refusing to publish a file whose name the repository already holds with other bytes:\n  " \
                            "#{conflicts.uniq.join("\n  ")}\n" \
                            "a published file never changes: give the package a new version (relspec compile does " \
                            "when its debian/ changes) instead of rebuilding the same one"
      end
    end
  end
end
