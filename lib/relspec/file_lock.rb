# frozen_string_literal: true

require "fileutils"

module Relspec
  # The one flock of relspec: a lock file in a folder, held while a block
  # runs (the target lock of build and publish, the repository lock of
  # publish). The kernel drops it when the holder dies, so a killed run
  # never leaves a stale lock behind.
  module FileLock
    # The lock file cannot be made or opened (+path+: the lock file, or its
    # folder when that is no folder; the reason).
    class Unavailable < StandardError
      attr_reader :path

      def initialize(path, reason)
        super(reason)
        @path = path
      end
    end

    # Why +dir+ cannot hold a lock file when it, or a folder above it, is a file.
    NOT_A_FOLDER = "it, or a folder above it, is a file, not a folder"

    module_function

    # Yields while this process holds +name+ in +dir+ (made if missing).
    # +shared+: a shared lock (readers beside each other). When another
    # process holds it, +busy+ is called with the open lock file (to name
    # the holder, Builder::TargetLock): it raises to refuse, or returns to
    # wait until the lock is free.
    def hold(dir, name, busy:, shared: false)
      file = open_file(dir, name)
      mode = shared ? File::LOCK_SH : File::LOCK_EX
      begin
        unless file.flock(mode | File::LOCK_NB)
          busy.call(file)
          file.flock(mode)
        end
        yield
      ensure
        file.close
      end
    end

    def open_file(dir, name)
      FileUtils.mkdir_p(dir)
      File.open(File.join(dir, name), File::RDWR | File::CREAT, 0o644)
    rescue Errno::EEXIST, Errno::ENOTDIR # mkdir_p's bare "File exists" where a file is in the way
      raise Unavailable.new(dir, NOT_A_FOLDER)
    rescue SystemCallError => e
      raise Unavailable.new(File.join(dir, name), e.message.sub(/ @ .*/, ""))
    end
    private_class_method :open_file
  end
end
