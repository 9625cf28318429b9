# frozen_string_literal: true

module Relspec
  # A place in a file that a person can jump to. Lines and columns are 1-based,
  # like every editor and compiler shows them; a location may name only a file.
  Location = Struct.new(:file, :line, :column, keyword_init: true) do
    def self.file_only(file)
      new(file: file).freeze
    end

    def self.at(file, line, column)
      new(file: file, line: line, column: column).freeze
    end

    def to_s
      return file.to_s unless line

      "#{file}:#{line}:#{column}"
    end
  end
end
