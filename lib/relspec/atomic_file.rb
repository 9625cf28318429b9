# frozen_string_literal: true

require "fileutils"
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
      stream(path) { |file| file.write(content) }
    end

    # Copies the file at +source+ to +path+ when their bytes differ, as
    # #update: streamed, never whole in memory (a build log can be of any
    # size). The source is opened without following a link. True if written.
    def copy(path, source)
      return false if File.file?(path) && FileUtils.compare_file(path, source)

      stream(path) { |file| File.open(source, File::RDONLY | File::NOFOLLOW) { |from| IO.copy_stream(from, file) } }
      true
    end

    # Yields the temporary file to write into, then puts it in place.
    def stream(path)
      dir = File.dirname(path)
      temporary = Temporaries.path(dir, File.basename(path))
      File.open(temporary, File::WRONLY | File::CREAT | File::EXCL, 0o644) do |file|
        file.binmode
        yield file
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
