# frozen_string_literal: true

require "fileutils"
require_relative "../atomic_file"
require_relative "../error"
require_relative "../printable"
require_relative "../unlinked_path"

module Relspec
  module Report
    # The folder a status page is written into (<out>/<release>/report/,
    # <repository>/report/): the page, and below logs/ a copy of each log
    # it links to, the copies no longer linked removed. relspec is its only
    # writer: a symbolic link in it (the folder itself, logs/, a target's
    # folder, a copy) would put the page or the logs into a folder relspec
    # did not make, and the clean-up would delete that folder's files. One is
    # refused, naming it, before anything is written (#check).
    class Folder
      LOGS = "logs"
      WHY = "relspec writes the report only inside %s and never through a link (its clean-up would delete the " \
            "files the link leads to); remove the link and run again"

      attr_reader :dir

      def initialize(dir)
        @dir = dir
      end

      # Raises Error naming the first link among what #write of +logs+
      # (link => file) and the page +file_name+ would touch.
      def check(logs, file_name)
        why = format(WHY, @dir)
        [file_name, LOGS, *logs.keys].each do |relative|
          UnlinkedPath.check(File.dirname(@dir), File.join(File.basename(@dir), relative), why: why)
        end
        linked = entries.find { |path| File.symlink?(path) }
        raise Error, "#{Printable.text(linked)} is a symbolic link (to #{Printable.text(File.readlink(linked))}): #{why}" if linked
      end

      # Writes +text+ as +file_name+ with a copy of each of +logs+ (link =>
      # file) and removes the copies no longer linked. Returns the page's path.
      def write(text, logs, file_name)
        check(logs, file_name)
        logs.each do |link, file|
          FileUtils.mkdir_p(File.dirname(File.join(@dir, link)))
          AtomicFile.copy(File.join(@dir, link), file)
        end
        FileUtils.mkdir_p(@dir)
        entries.each do |path|
          FileUtils.rm_f(path) if File.file?(path) && !logs.key?(path.delete_prefix("#{@dir}/"))
        end
        path = File.join(@dir, file_name)
        AtomicFile.update(path, text)
        path
      end

      private

      # Every path below logs/, without following a link.
      def entries(folder = File.join(@dir, LOGS))
        return [] if File.symlink?(folder) || !File.directory?(folder)

        Dir.children(folder).sort.flat_map do |name|
          path = File.join(folder, name)
          [path, *entries(path)]
        end
      end
    end
  end
end
