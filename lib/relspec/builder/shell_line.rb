# frozen_string_literal: true

module Relspec
  module Builder
    # Command lines written into shell scripts (Slurm jobs) so that a person
    # reads them as typed: words of safe characters stay bare, anything
    # else is single-quoted (Shellwords would write "--chroot\=…").
    module ShellLine
      SAFE = %r{\A[A-Za-z0-9_@%+=:,./~-]+\z}

      module_function

      def quote(word)
        word = word.to_s
        return word if word.match?(SAFE) && !word.start_with?("~")

        "'#{word.gsub("'", %q('\\\\''))}'"
      end

      def join(words)
        words.map { |word| quote(word) }.join(" ")
      end
    end
  end
end
