# frozen_string_literal: true

require "fileutils"
require "open3"
require "tmpdir"
require "zlib"
require_relative "../error"
require_relative "dwz_links"

module Relspec
  module Builder
    # Makes the ABI dumps of one build: every shared library its .debs ship
    # (an ELF file named lib*.so or lib*.so.N…, not a link), described by
    # libabigail's `abidw` from the library and the debug information the
    # build's -dbgsym .deb holds (dh_strip moved it there; abidw finds it by
    # build id under usr/lib/debug). Each dump is gzip-compressed with no
    # name and no time in its header, so the same library gives the same
    # bytes (abidw is told to leave out the paths a build folder would put
    # in).
    class AbiDumper
      # What a dump of library +library+ is stored as, +path+ the file.
      Dump = Struct.new(:library, :path, keyword_init: true)

      LIBRARY = /\Alib[A-Za-z0-9._+-]*\.so(?:\.[0-9]+)*\z/
      # An oroGen typekit's type registry (TypeRegistry), kept as it is.
      REGISTRY = /\A[A-Za-z0-9_][A-Za-z0-9._+-]*\.tlb\z/
      REGISTRY_DIR = File.join("share", "orogen")
      ELF = "\x7FELF".b
      DEBUG_ROOT = File.join("usr", "lib", "debug")
      ABIDW = ["abidw", "--no-corpus-path", "--no-comp-dir-path"].freeze

      # +run+: called with (command, log:) to run a tool (Builder::Tool#run
      # bound to the source); raises when the tool fails.
      def initialize(run)
        @run = run
      end

      SUFFIX = ".abi.xml.gz"

      # The library a dump file at +path+ describes, nil when +path+ is no dump.
      def self.library_of(path)
        name = File.basename(path)
        return nil unless name.end_with?(SUFFIX)

        library = name.delete_suffix(SUFFIX)
        dumped?(library) ? library : nil
      end

      # True for the name of a library or type registry relspec dumps.
      def self.dumped?(name)
        name.match?(LIBRARY) || name.match?(REGISTRY)
      end

      # True when +name+ (a dumped one) is an oroGen type registry.
      def self.registry?(name)
        name.match?(REGISTRY)
      end

      # The dumps of the libraries in +debs+, written into +dir+ as
      # <library>.abi.xml.gz, then the oroGen type registries they ship
      # (<typekit>.tlb.abi.xml.gz, the .tlb compressed as it is); none when
      # no .deb ships either.
      def dump(debs, dir, log:)
        Dir.mktmpdir("relspec-abi") do |root|
          debs.sort.each { |deb| @run.call(["dpkg-deb", "-x", deb, root], log: log) }
          DwzLinks.add(File.join(root, DEBUG_ROOT))
          libraries(root).filter_map { |library| library_dump(library, root, dir, log) } +
            registries(root).map { |registry| keep(registry, dir) }
        end
      end

      # A dump is a by-product of the build: abidw failing on a library
      # (a toolchain it does not read) leaves that library without a dump
      # (`relspec abi` then says it has none), said in the build's log,
      # and never fails a package that built.
      def library_dump(library, root, dir, log)
        FileUtils.mkdir_p(dir)
        xml = File.join(root, "#{File.basename(library)}.xml")
        @run.call([*ABIDW, "--debug-info-dir", File.join(root, DEBUG_ROOT), "--out-file", xml, library], log: log)
        path = File.join(dir, "#{File.basename(library)}#{SUFFIX}")
        AbiDumper.compress(xml, path)
        Dump.new(library: File.basename(library), path: path).freeze
      rescue ToolError => e
        File.open(log, "a") { |file| file.puts("relspec: no ABI dump of #{File.basename(library)}: #{e.message}") }
        nil
      end

      # The type registries under +root+ (share/orogen/*.tlb of a prefix).
      def registries(root)
        Dir.glob(File.join(root, "**", REGISTRY_DIR, "*.tlb")).select do |path|
          File.basename(path).match?(REGISTRY) && !File.symlink?(path) && File.file?(path)
        end.sort_by { |path| [File.basename(path), path] }.uniq { |path| File.basename(path) }
      end

      # gzip without the file name and with time 0 in its header.
      def self.compress(from, to)
        File.open(to, "wb") do |file|
          gzip = Zlib::GzipWriter.new(file, Zlib::BEST_COMPRESSION)
          gzip.mtime = 0
          File.open(from, "rb") { |input| IO.copy_stream(input, gzip) }
          gzip.finish
        end
      end

      def keep(registry, dir)
        FileUtils.mkdir_p(dir)
        path = File.join(dir, "#{File.basename(registry)}#{SUFFIX}")
        AbiDumper.compress(registry, path)
        Dump.new(library: File.basename(registry), path: path).freeze
      end

      # The shared libraries under +root+ outside the debug files, by name.
      def libraries(root)
        debug = File.join(root, DEBUG_ROOT)
        Dir.glob(File.join(root, "**", "lib*.so*")).select do |path|
          File.basename(path).match?(LIBRARY) && !path.start_with?("#{debug}/") && !File.symlink?(path) &&
            File.file?(path) && File.binread(path, 4) == ELF
        end.sort_by { |path| [File.basename(path), path] }.uniq { |path| File.basename(path) }
      end
    end
  end
end
