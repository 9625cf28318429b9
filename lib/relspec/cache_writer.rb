# frozen_string_literal: true

require "fileutils"
require_relative "atomic_file"
require_relative "error"

module Relspec
  # The one way an entry goes into one of relspec's caches (CacheDir). A
  # cache is only ever a shortcut: an entry that cannot be written (a
  # read-only or full file system, a directory in the way) costs speed,
  # never the run. The first such entry is noted on +notes+ in one line;
  # later ones are skipped without a word, so that one run says it once
  # however many caches share the writer.
  class CacheWriter
    # +notes+: where the one line about an unwritable cache goes (nil: nowhere).
    def initialize(notes: $stderr)
      @notes = notes
      @noted = false
    end

    # Writes +bytes+ at +path+ (its folders made); true when written.
    def write(path, bytes)
      FileUtils.mkdir_p(File.dirname(path))
      AtomicFile.write(path, bytes)
      true
    rescue SystemCallError, Relspec::Error => e
      note(path, e)
      false
    end

    private

    def note(path, error)
      return if @noted

      @noted = true
      reason = error.message.sub(/ @ .*/, "").sub(/\Acannot write \S+: /, "").sub(/ - .*\z/, "")
      @notes&.puts("relspec: note: the cache entry #{path} cannot be written (#{reason}); " \
                   "going on without it (only slower)")
    end
  end
end
