# frozen_string_literal: true

module Relspec
  # Paths in messages and in Result objects as the user would type them:
  # relative to the current folder when they are below it.
  module DisplayPath
    def self.of(path)
      full = File.expand_path(path)
      cwd = Dir.pwd
      return "." if full == cwd

      full.start_with?("#{cwd}/") ? full.delete_prefix("#{cwd}/") : full
    end
  end
end
