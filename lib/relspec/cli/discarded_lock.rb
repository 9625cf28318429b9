# frozen_string_literal: true

module Relspec
  module CLI
    # Says what --discard-lock costs when it was used on a lock that could
    # not be read: the history that decides revisions is gone.
    module DiscardedLock
      def self.warn(result, err)
        return unless result.previous.nil? && File.exist?(result.lock_path)

        err.puts("relspec: warning: discarding #{result.lock_path}, which cannot be read: the revisions and debian/ " \
                 "digests of earlier builds are forgotten; revisions the release's repository holds are not given again")
      end
    end
  end
end
