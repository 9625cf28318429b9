# frozen_string_literal: true

require "digest"
require "fileutils"
require "find"
require_relative "../error"

module Relspec
  module Publish
    # A publish changes the live repository only by switching to a new state
    # that is complete. reprepro keeps what a repository holds in Berkeley
    # DB files (db/) that it changes in place, without a journal, and a
    # refused or killed reprepro can leave them half-changed. So reprepro
    # works on a copy of conf/, db/ and dists/ in WORK (`--confdir`,
    # `--dbdir`, `--distdir`; the pool is shared: it only gains files, the
    # unreferenced ones are deleted after the switch), while the live
    # database is locked with reprepro's own lock (LiveLock). When the copy
    # is complete, READY records the digests of the live state it started
    # from and of the new state; then each folder is switched by two
    # renames, db/ last.
    #
    # A publish that finds WORK was interrupted:
    # - without READY it never touched the live repository: WORK goes;
    # - with READY it is switched in when the live state is still the one
    #   it started from and the new state still has the recorded digest;
    #   otherwise (the repository changed by hand since, or the copy is
    #   damaged) the folders already switched are put back and WORK goes.
    # Nothing live is ever deleted: only WORK, relspec's own copy.
    #
    # Runs under RepositoryLock: no other relspec publisher touches WORK.
    class Transaction
      WORK = ".relspec-publish-work"
      READY = "READY"
      FOLDERS = %w[conf dists db].freeze # db last: its switch ends the publish
      # The marker of the database copy an earlier relspec made.
      OLD_MARKER = ".relspec-publish-unfinished"
      OLD_COPY = ".relspec-db-before-publish"

      attr_reader :work

      def initialize(repository)
        @repository = repository
        @work = File.join(repository, WORK)
      end

      # What an interrupted publish left: :discarded (it had not started to
      # switch), :finished (switched in now), :abandoned (not used: the
      # repository changed since, or its copy is damaged), nil (none).
      def recover
        refuse_old_marker
        return nil unless File.directory?(@work)
        return discard(:discarded) unless File.exist?(File.join(@work, READY))
        return discard(:finished) unless File.exist?(File.join(@work, "db"))

        base, fresh = File.read(File.join(@work, READY)).split
        if digest(FOLDERS.map { |name| old_path(name) }) == base && digest(FOLDERS.map { |name| new_path(name) }) == fresh
          switch
          return :finished
        end
        put_back
        discard(:abandoned)
      rescue SystemCallError => e
        raise PublishError, "cannot recover the interrupted publish of #{@repository} (#{@work}): " \
                            "#{e.message.sub(/ @ .*/, '')}; fix that and publish again"
      end

      # A db/ renamed into WORK by a switch that was killed before its second
      # rename goes back first, so that the live database exists to be locked.
      def undo_half_rename
        old = File.join(@work, "old-db")
        live = File.join(@repository, "db")
        File.rename(old, live) if File.directory?(old) && !File.exist?(live)
      end

      # Makes WORK a copy of the live conf/, dists/ and db/ (reprepro's lock
      # file left out) and yields its folders; then records READY and
      # switches. WORK goes when the block fails.
      def run
        FileUtils.rm_rf(@work)
        FileUtils.mkdir_p(@work)
        base = digest(FOLDERS.map { |name| File.join(@repository, name) })
        FOLDERS.each { |name| copy(File.join(@repository, name), File.join(@work, name)) }
        result = yield(FOLDERS.to_h { |name| [name.to_sym, File.join(@work, name)] })
        File.write(File.join(@work, READY), "#{base} #{digest(FOLDERS.map { |name| File.join(@work, name) })}\n")
        switch_or_explain
        result
      rescue StandardError, Interrupt
        FileUtils.rm_rf(@work) unless File.exist?(File.join(@work, READY))
        raise
      end

      private

      def switch_or_explain
        switch
      rescue SystemCallError => e
        raise PublishError, "cannot switch #{@repository} to the published state in #{@work}: " \
                            "#{e.message.sub(/ @ .*/, '')}; fix that and publish again (it finishes the switch, " \
                            "or puts back what it had replaced)"
      end

      def refuse_old_marker
        marker = File.join(@repository, OLD_MARKER)
        return unless File.exist?(marker)

        db = File.join(@repository, "db")
        copy = File.join(@repository, OLD_COPY)
        raise PublishError, "#{marker}: a publish by an earlier relspec was interrupted here and its database " \
                            "may be damaged; nothing was changed. If `reprepro -b #{@repository} check` succeeds, " \
                            "#{db} is whole: remove #{marker} and #{copy}, then publish again. If it fails, " \
                            "#{copy} is the database before that publish: replace #{db} with it, remove #{marker}, " \
                            "then publish again"
      end

      def copy(from, to)
        FileUtils.mkdir_p(to)
        return unless File.directory?(from)

        (Dir.children(from) - ["lockfile"]).each { |name| FileUtils.cp_r(File.join(from, name), to, preserve: true) }
      end

      # Each folder: live one into WORK (old-X), new one live. A folder
      # whose new state is already live is skipped (a recovery goes on).
      def switch
        FOLDERS.each do |name|
          fresh = File.join(@work, name)
          next unless File.exist?(fresh)

          live = File.join(@repository, name)
          File.rename(live, File.join(@work, "old-#{name}")) if File.exist?(live)
          File.rename(fresh, live)
        end
        FileUtils.rm_rf(@work)
      end

      # The live folders a switch had replaced come back.
      def put_back
        FOLDERS.each do |name|
          old = File.join(@work, "old-#{name}")
          next unless File.exist?(old)

          live = File.join(@repository, name)
          File.rename(live, File.join(@work, "dropped-#{name}")) if File.exist?(live)
          File.rename(old, live)
        end
      end

      def discard(outcome)
        FileUtils.rm_rf(@work)
        outcome
      end

      def old_path(name)
        old = File.join(@work, "old-#{name}")
        File.exist?(old) ? old : File.join(@repository, name)
      end

      def new_path(name)
        fresh = File.join(@work, name)
        File.exist?(fresh) ? fresh : File.join(@repository, name)
      end

      # One SHA256 over the folders' files (names, link targets, bytes),
      # reprepro's lock file left out.
      def digest(folders)
        sha = Digest::SHA256.new
        folders.each_with_index do |folder, index|
          sha << "#{index}\0"
          next unless File.directory?(folder)

          entries(folder).each do |relative|
            path = File.join(folder, relative)
            sha << relative << "\0"
            if File.symlink?(path)
              sha << "->" << File.readlink(path)
            elsif File.file?(path)
              sha << File.size(path).to_s << "\0"
              File.open(path, "rb") { |file| sha << file.read(1 << 20).to_s until file.eof? }
            end
            sha << "\0"
          end
        end
        sha.hexdigest
      end

      def entries(folder)
        list = []
        Find.find(folder) do |path|
          relative = path.delete_prefix(folder).delete_prefix("/")
          list << relative unless relative.empty? || relative == "lockfile"
        end
        list.sort
      end
    end
  end
end
