# frozen_string_literal: true

require "open3"
require_relative "../error"

module Relspec
  module Publish
    # reprepro on one base directory (its pool), optionally with its
    # configuration, database and dists/ elsewhere (+dirs+: conf:, db:,
    # dists:, a Transaction's copy; pool files that become unreferenced
    # there are kept, since the live database may still list them). A
    # failure is one PublishError naming the command, its exit status and
    # its output.
    class Reprepro
      OUTPUT_LINES = 30 # lines of a failed command's output kept in the message

      def initialize(base, dirs = nil)
        @base = base
        @options = []
        return unless dirs

        @options = ["--confdir", dirs.fetch(:conf), "--dbdir", dirs.fetch(:db), "--distdir", dirs.fetch(:dists),
                    "--keepunreferencedfiles"]
      end

      def includedsc(codename, dsc)
        run("includedsc", codename, dsc)
      end

      def includedeb(codename, debs)
        run("includedeb", codename, *debs)
      end

      # The source packages +codename+ holds, as "source version" lines.
      def sources(codename)
        run("--architecture", "source", "--list-format", "${package} ${version}\n", "list", codename).lines.map(&:chomp)
      end

      def export
        run("export")
      end

      # The pool files the database holds ("pool/main/…" paths): what was
      # published, unlike a file an interrupted reprepro left in pool/.
      def pool_files
        run("_listchecksums").lines.map { |line| line.split(" ", 2).first }.compact
      end

      def deleteunreferenced
        run("deleteunreferenced")
      end

      def run(*args)
        output, status = Open3.capture2e("reprepro", "--basedir", @base, *@options, *args)
        return output if status.success?

        raise PublishError, "reprepro #{args.first} failed (exit status #{status.exitstatus}) in #{@base}:\n" \
                            "#{output.lines.last(OUTPUT_LINES).join.rstrip}"
      rescue SystemCallError => e
        raise PublishError, "cannot run reprepro: #{e.message.sub(/ @ .*/, '')} (install the reprepro package)"
      end
    end
  end
end
