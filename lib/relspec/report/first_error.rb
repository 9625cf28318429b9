# frozen_string_literal: true

require "stringio"
require_relative "../error"
require_relative "../printable"

module Relspec
  module Report
    # The first lines of a build log that say what went wrong: what a
    # maintainer looks for first, shown inline on the page. The host
    # backend's log names each command it runs ("$ command"): only the last
    # one's output is searched, since an earlier command's error was
    # answered (dpkg-checkbuilddeps names the release's own build-dependencies
    # before they are laid over /opt). The error line comes with the
    # indented lines that continue it (CMake's message). A log is untrusted
    # text of any size: it is read as a stream, line by line, up to
    # MAX_BYTES (a line up to MAX_LINE_BYTES, the rest of it skipped), so
    # memory stays bounded whatever the log; control characters are
    # dropped and each line shown is cut at MAX_CHARS.
    module FirstError
      MAX_BYTES = 64 * 1024 * 1024
      MAX_LINE_BYTES = 64 * 1024
      MAX_CHARS = 300
      MAX_CONTINUATION = 4
      COMMAND = /\A\$ /
      # CMake's "CMake Error at …", compilers' "error:", make's "*** …
      # Error 1", dpkg's "dpkg-buildpackage: error:", "fatal error:".
      ERROR = /\b(error|fatal)\b|\*\*\*/i
      # Lines that name errors without being one.
      NOT_AN_ERROR = /-Werror|\berror(s)?\.(c|h|o|cpp)\b|\b0 errors?\b|error_log|liberror/i
      CONTINUATION = /\A[ \t]+\S/

      module_function

      # The first error line of the log at +path+, nil when none (or no log).
      # The log itself is opened without following a link (the report
      # refuses linked logs before, Report::Reading).
      def of_file(path)
        return nil unless path && File.file?(path)

        File.open(path, File::RDONLY | File::NOFOLLOW) { |file| of_io(file.binmode) }
      rescue Errno::ELOOP
        raise Error, "#{Printable.text(path)} is a symbolic link: the report reads only the logs a build wrote"
      end

      def of_text(text)
        of_io(StringIO.new(text.b))
      end

      # The search over the lines of +io+, each line seen once: an error
      # line found is forgotten when a later command starts.
      def of_io(io)
        found = nil
        collecting = false
        each_line(io) do |line|
          if line.match?(COMMAND)
            found = nil
            collecting = false
          elsif collecting && found.size <= MAX_CONTINUATION && line.match?(CONTINUATION)
            found << line
          elsif found.nil? && line.match?(ERROR) && !line.match?(NOT_AN_ERROR)
            found = [line]
            collecting = true
          else
            collecting = false
          end
        end
        found&.map { |line| clean(line) }&.join("\n")
      end

      # Yields each line of +io+ (its first MAX_LINE_BYTES) within the
      # first MAX_BYTES of it.
      def each_line(io)
        left = MAX_BYTES
        partial = false
        while left.positive? && (chunk = io.gets("\n", [MAX_LINE_BYTES, left].min))
          left -= chunk.bytesize
          yield chunk unless partial
          partial = !chunk.end_with?("\n")
        end
      end

      # One line of text: valid UTF-8, no control characters, at most MAX_CHARS.
      def clean(raw)
        text = raw.dup.force_encoding(Encoding::UTF_8).scrub("?").gsub(/[[:cntrl:]]/, " ").strip
        text.size > MAX_CHARS ? "#{text[0, MAX_CHARS - 1]}…" : text
      end
    end
  end
end
