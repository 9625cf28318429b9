# frozen_string_literal: true

require "digest"
require_relative "../error"

module Relspec
  module Publish
    # A repository must never receive two different files under one name
    # (DESIGN §5): apt clients that saw the first would fail their checksum
    # on the second. reprepro refuses too, but only in the middle of a batch;
    # this check refuses the whole publication before anything is included,
    # and names both files.
    module PoolGuard
      module_function

      # +items+: Upload::Item; raises PublishError on the first conflict.
      def check(repository, items)
        conflicts = items.filter_map do |item|
          held = File.join(repository, item.pool)
          next unless File.file?(held)

          ours = Digest::SHA256.file(item.local).hexdigest
          theirs = Digest::SHA256.file(held).hexdigest
          "#{item.local} (sha256 #{ours}) differs from #{held} (sha256 #{theirs}), already published" unless ours == theirs
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
