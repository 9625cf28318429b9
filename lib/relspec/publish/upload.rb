# frozen_string_literal: true

require "digest"
require_relative "../apt/deb822"
require_relative "../debian/naming"
require_relative "../error"
require_relative "debug_symbols"

module Relspec
  module Publish
    # What one built source package puts into the repository: its source
    # package (where compile wrote it) and the .debs the build produced, each
    # checked against what was recorded, and each with the name it gets in
    # reprepro's pool. Debug-symbol packages are left out unless the spec
    # asks for them (DebugSymbols); every recorded file is still checked.
    class Upload
      # +local+: the file here; +pool+: its path below the repository.
      Item = Struct.new(:local, :pool, keyword_init: true)

      attr_reader :source, :version, :dsc, :debs

      # +entry+: a Builder::BuildResults::Record (built); +target_dir+: the target's
      # folder of <out>, where compile and build wrote; +debug_symbols+:
      # the -dbgsym .debs are published too.
      def self.of(entry, target_dir, results_path, debug_symbols: false)
        new(entry, target_dir, results_path, debug_symbols: debug_symbols).tap(&:verify)
      end

      def initialize(entry, target_dir, results_path, debug_symbols: false)
        @entry = entry
        @source = entry.source
        @version = entry.version
        @target_dir = target_dir
        @results_path = results_path
        @dsc = File.join(target_dir, @source, Debian::Naming.dsc(@source, @version))
        @built = entry.files.map { |file| File.join(target_dir, file.name) }.select { |path| path.end_with?(".deb") }.sort
        @debs = DebugSymbols.select(@built, included: debug_symbols)
      end

      # Every recorded file present with its recorded bytes, at least one
      # .deb, and the source package whole: otherwise nothing of it is
      # published.
      def verify
        @entry.files.each do |file|
          path = File.join(@target_dir, file.name)
          fail!("#{path} is missing") unless File.file?(path)
          actual = Digest::SHA256.file(path).hexdigest
          fail!("#{path} has changed since it was built (sha256 #{actual}, recorded #{file.sha256})") unless actual == file.sha256
        end
        fail!("the build produced no .deb") if @built.empty?
        fail!("the build produced only debug-symbol packages (#{@built.map { |path| File.basename(path) }.join(', ')})") if @debs.empty?
        source_files.each do |name, sha256|
          path = File.join(File.dirname(@dsc), name)
          fail!("#{path}, listed in #{@dsc}, is missing") unless File.file?(path)
          fail!("#{path} does not match #{@dsc}") unless Digest::SHA256.file(path).hexdigest == sha256
        end
      end

      def items
        [@dsc, *source_files.keys.map { |name| File.join(File.dirname(@dsc), name) }, *@debs].map do |path|
          Item.new(local: path, pool: File.join(pool_dir, File.basename(path)))
        end
      end

      # reprepro's pool layout: pool/<component>/<l or libx>/<source>/.
      def pool_dir
        initial = @source.start_with?("lib") && @source.size > 3 ? @source[0, 4] : @source[0]
        File.join("pool", "main", initial, @source)
      end

      private

      # name => sha256 of the files the .dsc lists.
      def source_files
        @source_files ||= begin
          fail!("its source package #{@dsc} is missing (run relspec compile)") unless File.file?(@dsc)
          stanza = Apt::Deb822.parse(File.read(@dsc).sub(/\A-----BEGIN PGP SIGNED MESSAGE-----\n(?:.+\n)*\n/, "")).first || {}
          stanza.fetch("Checksums-Sha256", "").lines.map(&:split).reject(&:empty?).to_h { |sha256, _size, name| [name, sha256] }
        rescue Apt::Deb822::ParseError => e
          fail!("#{@dsc} cannot be read: #{e.message}")
        end
      end

      def fail!(why)
        raise PublishError, "#{@source} #{@version} (#{@results_path}) cannot be published: #{why}"
      end
    end
  end
end
