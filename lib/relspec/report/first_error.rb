# frozen_string_literal: true

module Relspec
  module Report
    # The first lines of a build log that say what went wrong: what a
    # maintainer looks for first, shown inline on the page. The host
    # backend's log names each command it runs ("$ command"): only the last
    # one's output is searched, since an earlier command's error was
    # answered (dpkg-checkbuilddeps names the release's own build-dependencies
    # before they are laid over /opt). The error line comes with the
    # indented lines that continue it (CMake's message). A log is untrusted
    # text: read up to MAX_BYTES, control characters dropped, each line cut
    # at MAX_CHARS.
    module FirstError
      MAX_BYTES = 16 * 1024 * 1024
      MAX_CHARS = 300
      MAX_CONTINUATION = 4
      COMMAND = /\A\$ /
      # CMake's "CMake Error at …", compilers' "error:", make's "*** …
      # Error 1", dpkg's "dpkg-buildpackage: error:", "fatal error:".
      ERROR = /\b(error|fatal)\b|\*\*\*/i
      # Lines that name errors without being one.
      NOT_AN_ERROR = /-Werror|\berror(s)?\.(c|h|o|cpp)\b|\b0 errors?\b|error_log|liberror/i

      module_function

      # The first error line of the log at +path+, nil when none (or no log).
      def of_file(path)
        return nil unless path && File.file?(path)

        File.open(path, "rb") { |file| of_text(file.read(MAX_BYTES).to_s) }
      end

      def of_text(text)
        lines = text.each_line.to_a
        last_command = lines.rindex { |line| line.match?(COMMAND) }
        lines = lines.drop(last_command + 1) if last_command
        at = lines.index { |line| line.match?(ERROR) && !line.match?(NOT_AN_ERROR) }
        return nil unless at

        continued = lines.drop(at + 1).take(MAX_CONTINUATION).take_while { |line| line.match?(/\A[ \t]+\S/) }
        [lines[at], *continued].map { |line| clean(line) }.join("\n")
      end

      # One line of text: valid UTF-8, no control characters, at most MAX_CHARS.
      def clean(raw)
        text = raw.dup.force_encoding(Encoding::UTF_8).scrub("?").gsub(/[[:cntrl:]]/, " ").strip
        text.size > MAX_CHARS ? "#{text[0, MAX_CHARS - 1]}…" : text
      end
    end
  end
end
