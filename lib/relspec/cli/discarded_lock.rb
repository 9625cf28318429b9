# frozen_string_literal: true

module Relspec
  module CLI
    # Says what --discard-lock costs when it was used on a lock that could
    # not be read: the history that decides revisions is gone.
    module DiscardedLock
      # +planned+: a Plan::Result.
      def self.warn(planned, err)
        return unless discarded?(planned)

        err.puts("relspec: warning: discarding #{planned.lock_path}, which cannot be read: the revisions and debian/ " \
                 "digests of earlier builds are forgotten; revisions the release's repository holds are not given again")
      end

      def self.discarded?(planned)
        !planned.lock_read? && File.exist?(planned.lock_path)
      end
    end
  end
end
