# frozen_string_literal: true

require "fileutils"
require_relative "lock"
require_relative "../yaml/writer"
require_relative "../atomic_file"

module Relspec
  module Plan
    # Writes a Lock: keys in a fixed order, everything sorted, no timestamps
    # or host paths, so the same lock is always the same bytes. LockParser
    # reads exactly what this writes.
    module LockGenerator
      module_function

      def dump(lock)
        Yaml::Writer.dump(lock.to_h)
      end

      # True if the file changed.
      def write(path, lock)
        FileUtils.mkdir_p(File.dirname(path))
        AtomicFile.update(path, dump(lock))
      end
    end
  end
end
