# frozen_string_literal: true

require "fileutils"
require_relative "../error"

module Relspec
  module Publish
    # reprepro keeps what a repository holds in Berkeley DB files (db/) that
    # it changes in place, without a journal: a reprepro killed in the middle
    # of a write (SIGKILL, the OOM killer, a lost machine) can leave them
    # unreadable ("BDB0002 __fop_file_setup: Retry limit (100) exceeded"),
    # and no later reprepro can open the repository. A publish therefore
    # copies db/ aside before its first reprepro call and marks the
    # repository unfinished; the marker goes when the publish has ended. A
    # publish that finds the marker puts the copy back: the repository is
    # again what the last finished publish left, and this publish includes
    # everything again (reprepro registers pool files it finds with the
    # bytes it expects; PoolGuard has refused any other bytes before).
    #
    # Runs under RepositoryLock: no other relspec publisher touches db/.
    module DatabaseSnapshot
      MARKER = ".relspec-publish-unfinished"
      COPY = ".relspec-db-before-publish"

      module_function

      # Yields whether an unfinished publish was rolled back first.
      def guard(repository)
        restored = restore(repository)
        take(repository)
        result = yield restored
        finish(repository)
        result
      end

      # Puts the copy back when the last publish did not finish; true if
      # it did so. Without a copy the last publish started from no database:
      # the database goes.
      def restore(repository)
        return false unless File.exist?(File.join(repository, MARKER))

        db = File.join(repository, "db")
        FileUtils.rm_rf(db)
        copy = File.join(repository, COPY)
        FileUtils.cp_r(copy, db) if File.directory?(copy)
        true
      rescue SystemCallError => e
        raise PublishError, "cannot roll back the unfinished publish of #{repository}: #{e.message.sub(/ @ .*/, '')}"
      end

      # The copy, then the marker: a publish killed while copying finds no
      # marker and an old or partial copy, which the next #take replaces.
      def take(repository)
        db = File.join(repository, "db")
        copy = File.join(repository, COPY)
        FileUtils.rm_rf(copy)
        if File.directory?(db)
          FileUtils.mkdir_p(copy)
          (Dir.children(db) - ["lockfile"]).each { |name| FileUtils.cp_r(File.join(db, name), copy) }
        end
        File.write(File.join(repository, MARKER), "")
      rescue SystemCallError => e
        raise PublishError, "cannot keep a copy of #{db} before publishing: #{e.message.sub(/ @ .*/, '')}"
      end

      # The marker first: once it is gone, the copy is never used again.
      def finish(repository)
        File.delete(File.join(repository, MARKER))
        FileUtils.rm_rf(File.join(repository, COPY))
      end
    end
  end
end
