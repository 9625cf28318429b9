# frozen_string_literal: true

require_relative "../publish"
require_relative "../printable"

module Relspec
  module CLI
    # `relspec publish SPEC`: the built packages into the release's
    # repository, then its osdeps files.
    class PublishCommand
      def initialize(path:, out:, target:, timeout:, out_io:, err_io:)
        @path = path
        @out = out
        @target = target
        @timeout = timeout
        @io = out_io
        @err = err_io
      end

      def call
        result = Publish.run(@path, out: @out, target: @target, timeout: @timeout,
                                    waiting: ->(what) { @err.puts("waiting for #{Printable.text(what)} to finish…") })
        @err.puts(Publish::StaleRepreproLock.note(result.stale_lock)) if result.stale_lock
        note_recovered(result)
        result.abi_rebuilt.each { |rebuilt| note_rebuilt(rebuilt) }
        result.targets.each { |target| report(target) }
        @io.puts("#{result.release}: #{Printable.text(result.repository)}: #{result.osdeps_written.zero? ? 'osdeps unchanged' : "wrote #{result.osdeps_written} osdeps files"}")
        note_missing(result.osdeps_missing)
        @io.puts("status page: #{Printable.text(result.report)}")
        0
      end

      private

      RECOVERED = {
        discarded: "had not started to change it: its unfinished copy was removed, the repository is as the last " \
                   "finished publish left it",
        finished: "had completed its new state: it was switched in now",
        abandoned: "left a new state that no longer matches the repository (changed since, or damaged): it was " \
                   "not used, the repository is as it was before that publish"
      }.freeze

      def note_recovered(result)
        return unless result.recovered

        @err.puts("the last publish into #{result.repository} was interrupted and #{RECOVERED.fetch(result.recovered)}")
      end

      # An ABI index that could not be read, made again (Abi::RebuiltDumps).
      def note_rebuilt(rebuilt)
        index = File.join(rebuilt.dumps.dir, Abi::PublishedDumps::FILE_NAME)
        # names of files a repository holds: escaped, as every value from one
        left_out = rebuilt.left_out.map { |path| Printable.text(path.delete_prefix("#{rebuilt.dumps.dir}/")) }
        @err.puts("the ABI index #{index} could not be read (#{rebuilt.problem}); made it again from the " \
                  "#{rebuilt.dumps.entries.size} dumps there that build-results.yml vouches for" \
                  "#{"; left out, as no build vouches for them: #{left_out.join(', ')}" unless left_out.empty?}")
      end

      # Planned packages the osdeps files leave out, counted per target (the
      # list is `relspec osdeps --from-repository`'s).
      def note_missing(missing)
        return if missing.empty?

        counts = missing.map { |line| line.split(" ", 2).first }.tally.map { |target, count| "#{target}: #{count}" }
        @err.puts("not in the repository yet, so not in its osdeps files: #{missing.size} planned packages " \
                  "(#{counts.join(', ')}); relspec osdeps SPEC --from-repository lists them")
      end

      def report(target)
        unless target.built
          @io.puts("#{target.target}: not built (no build-results.yml)")
          return
        end
        @io.puts("#{target.target}: #{target.published.size} published, #{target.held.size} already in the repository")
        target.published.each { |source| @io.puts("  published #{source}") }
        target.left_out.each do |entry|
          next if entry.status == "published"

          @io.puts("  not published: #{entry.source} (#{entry.status})")
        end
      end
    end
  end
end
