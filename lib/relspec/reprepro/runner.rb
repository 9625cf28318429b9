# frozen_string_literal: true

require "open3"
require_relative "../error"

module Relspec
  module Reprepro
    # reprepro on one base directory (its pool), for publish and mirror,
    # optionally with its configuration, database and dists/ elsewhere
    # (+dirs+: conf:, db:, dists:, publish's Transaction copy; pool files
    # that become unreferenced there are kept, since the live database may
    # still list them). A failure is one +error+ (the stage's kind:
    # PublishError for publish) naming the command, its exit status and the
    # end of its output.
    class Runner
      OUTPUT_LINES = 30 # lines of a failed command's output kept in the message

      def initialize(base, dirs = nil, error: ToolError)
        @base = base
        @error = error
        @options = []
        return unless dirs

        @options = ["--confdir", dirs.fetch(:conf), "--dbdir", dirs.fetch(:db), "--distdir", dirs.fetch(:dists),
                    "--keepunreferencedfiles"]
      end

      def includedsc(codename, dsc)
        run("includedsc", codename, dsc)
      end

      # +arch+: only the .debs of that architecture (and all).
      def includedeb(codename, debs, arch: nil)
        run("includedeb", codename, *debs, options: arch ? ["-A", arch] : [])
      end

      def remove(codename, names, arch:)
        run("remove", codename, *names, options: ["-A", arch])
      end

      # Every package +codename+ lists, as [name, version, part] ("source"
      # for a source package, else the architecture it is listed under).
      def packages(codename)
        run("list", codename, options: ["--list-format", "${package} ${version} ${$architecture}\n"])
          .lines.map(&:split).select { |fields| fields.size == 3 }
      end

      def export
        run("export")
      end

      # Forgets what the configuration no longer names (a dropped codename).
      def clearvanished
        run("clearvanished", options: ["--delete"])
      end

      # The pool files the database holds ("pool/main/…" paths): what was
      # published, unlike a file an interrupted reprepro left in pool/.
      def pool_files
        run("_listchecksums").lines.map { |line| line.split(" ", 2).first }.compact
      end

      def deleteunreferenced
        run("deleteunreferenced")
      end

      # reprepro's +command+ with its +args+; +options+ go before it.
      def run(command, *args, options: [])
        output, status = Open3.capture2e("reprepro", "--basedir", @base, *@options, *options, command, *args)
        return output if status.success?

        raise @error, "reprepro #{command} failed (exit status #{status.exitstatus}) in #{@base}:\n" \
                      "#{output.lines.last(OUTPUT_LINES).join.rstrip}"
      rescue SystemCallError => e
        raise @error, "cannot run reprepro: #{e.message.sub(/ @ .*/, '')} (install the reprepro package)"
      end
    end
  end
end
