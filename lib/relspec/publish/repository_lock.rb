# frozen_string_literal: true

require_relative "../error"
require_relative "../file_lock"
require_relative "../lock_holder"

module Relspec
  module Publish
    # One publisher at a time per repository: an exclusive flock on a file
    # in the repository's base folder, held from the first look at the pool
    # to the osdeps files. The pool check and reprepro's includes must see
    # the same repository, which reprepro's own lock (per command) cannot
    # promise. The kernel drops the lock when the process dies, so a crash
    # never leaves a stale lock behind.
    module RepositoryLock
      FILE_NAME = ".relspec-publish.lock"

      module_function

      # Yields once the lock is held; +waiting+ is called once (with who
      # holds it and since when, LockHolder) if another publisher holds it.
      def hold(repository, waiting: nil, &block)
        FileLock.hold(repository, FILE_NAME, busy: ->(file) { waiting&.call(LockHolder.of(file)) }, &block)
      rescue FileLock::Unavailable => e
        raise PublishError, "cannot lock the repository #{repository}: #{e.message}"
      end
    end
  end
end
