# frozen_string_literal: true

require "fileutils"
require_relative "../error"
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
      def hold(repository, waiting: nil)
        file = open_lock_file(repository)
        begin
          unless file.flock(File::LOCK_EX | File::LOCK_NB)
            waiting&.call(LockHolder.of(file))
            file.flock(File::LOCK_EX)
          end
          yield
        ensure
          file.close
        end
      end

      def open_lock_file(repository)
        FileUtils.mkdir_p(repository)
        File.open(File.join(repository, FILE_NAME), File::RDWR | File::CREAT, 0o644)
      rescue Errno::EEXIST, Errno::ENOTDIR # mkdir_p's "File exists" where a file is in the way
        raise PublishError, "cannot lock the repository #{repository}: it, or a folder above it, is a file, not a folder"
      rescue SystemCallError => e
        raise PublishError, "cannot lock the repository #{repository}: #{e.message.sub(/ @ .*/, '')}"
      end
    end
  end
end
