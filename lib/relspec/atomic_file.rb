# frozen_string_literal: true

require_relative "error"
require_relative "temporaries"

module Relspec
  # Writes a file so that readers see either the old or the new content,
  # never half of it: a temporary file in the same folder, then a rename.
  module AtomicFile
    module_function

    # Writes only when the content differs, so an unchanged output keeps
    # its mtime (and make-like tools see nothing to do). True if written.
    # Bytes against bytes: a UTF-8 string with non-ASCII text never equals
    # the binary read of the same file.
    def update(path, content)
      return false if File.file?(path) && File.binread(path) == content.b

      write(path, content)
      true
    end

    def write(path, content)
      dir = File.dirname(path)
      temporary = Temporaries.path(dir, File.basename(path))
      File.open(temporary, File::WRONLY | File::CREAT | File::EXCL, 0o644) do |file|
        file.binmode
        file.write(content)
        file.fsync
      end
      File.rename(temporary, path)
    rescue SystemCallError => e
      raise Error, "cannot write #{path}: #{e.message.sub(/ @ .*/, '').sub(/ - .*\z/, '')}"
    ensure
      File.unlink(temporary) if temporary && File.exist?(temporary)
    end
  end
end
