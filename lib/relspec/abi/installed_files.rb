# frozen_string_literal: true

require "digest"
require "fileutils"
require "open3"
require "rubygems/package"
require "tempfile"
require_relative "../error"
require_relative "../frozen"
require_relative "../elf_file"
require_relative "../builder/abi_dumper"

module Relspec
  module Abi
    # What a build installs: every file, link and shared library its
    # binary packages put on a machine, by path (without the leading "./"),
    # read from the .debs' data archives (`dpkg-deb --fsys-tarfile`), not
    # unpacked. The debug-symbol packages and usr/lib/debug are left out
    # (nothing builds against them), and so is each package's changelog
    # (changelog.Debian.gz, or changelog.gz of a native package), which
    # changes with every version by design.
    module InstalledFiles
      # +kind+: :file, :link (+content+: its target) or :library (a shared
      # library, as Dumper finds them: an ELF file named lib*.so*; compared
      # by its ABI dump, not its bytes); +content+: the SHA256 of a file's
      # or a library's bytes (an ELF file's without its debug links).
      Entry = Struct.new(:kind, :content, keyword_init: true)

      DEBUG_PACKAGE = /-dbgsym_[^_]+_[^_]+\.d?deb\z/
      LEFT_OUT = %r{\A(?:usr/lib/debug/|usr/share/doc/[^/]+/changelog(?:\.Debian)?(?:\.gz)?\z)}
      # Anything larger than this in one package is not a Rock library.
      MAX_FILE = 2 * 1024 * 1024 * 1024
      ELF_IN_MEMORY = 512 * 1024 * 1024

      module_function

      # Path => Entry of every file the .debs +debs+ install, frozen.
      def of(debs)
        entries = debs.reject { |deb| File.basename(deb).match?(DEBUG_PACKAGE) }.sort.each_with_object({}) do |deb, out|
          # Gem's tar reader seeks: the archive goes through a file
          Tempfile.create("relspec-data-tar") do |tar|
            extract(deb, tar)
            out.merge!(from_tar(tar, source: deb))
          end
        end
        Frozen.deep(entries)
      rescue Errno::ENOENT
        raise ToolError, "cannot run dpkg-deb (is dpkg installed?)"
      end

      # The non-debug .debs of +debs+ unpacked into the folder +root+ (what
      # abidiff reads the installed headers from).
      def unpack(debs, root)
        FileUtils.mkdir_p(root)
        debs.reject { |deb| File.basename(deb).match?(DEBUG_PACKAGE) }.sort.each do |deb|
          output, status = Open3.capture2e("dpkg-deb", "-x", deb, root)
          raise ToolError, "dpkg-deb -x #{deb} failed: #{output.strip}" unless status.success?
        end
      end

      def extract(deb, tar)
        Tempfile.create("relspec-dpkg-deb") do |error|
          pid = Process.spawn("dpkg-deb", "--fsys-tarfile", deb, out: tar, err: error)
          unless Process.wait2(pid).last.success?
            raise ToolError, "dpkg-deb --fsys-tarfile #{deb} failed: #{File.read(error.path).strip}"
          end
        end
        tar.rewind
      end

      # Path => Entry of the tar stream +io+ (a .deb's data archive, as
      # dpkg-deb checked and printed it); +source+ names it in errors.
      def from_tar(io, source:)
        out = {}
        Gem::Package::TarReader.new(io).each do |tar|
          path = tar.full_name.sub(%r{\A\./}, "").chomp("/")
          next if path.empty? || path.match?(LEFT_OUT) || tar.directory?

          out[path] = entry(tar, path, source)
        end
        out
      end

      def entry(tar, path, source)
        return Entry.new(kind: :link, content: tar.header.linkname).freeze if tar.symlink? || tar.header.typeflag == "1"
        raise ToolError, "#{source}: #{path} is larger than #{MAX_FILE} bytes" if tar.header.size > MAX_FILE

        head, digest = digest(tar)
        library = File.basename(path).match?(Builder::AbiDumper::LIBRARY) && head == Builder::AbiDumper::ELF
        Entry.new(kind: library ? :library : :file, content: digest).freeze
      end

      # [the first four bytes, the SHA256] of a tar entry; an ELF file's
      # (a program, a plugin, a Ruby extension) without its debug links and
      # build id (ElfFile::DEBUG_LINKS), held in memory up to ELF_IN_MEMORY
      # (beyond that its bytes as they are: it then differs, safely).
      def digest(tar)
        digest = Digest::SHA256.new
        first = tar.read(1 << 20) || ""
        head = first[0, 4]
        if head == ElfFile::MAGIC && tar.header.size <= ELF_IN_MEMORY
          bytes = first.b
          while (chunk = tar.read(1 << 20))
            bytes << chunk
          end
          return [head, Digest::SHA256.hexdigest(ElfFile.without_debug_links(bytes))]
        end

        digest << first
        while (chunk = tar.read(1 << 20))
          digest << chunk
        end
        [head, digest.hexdigest]
      end
    end
  end
end
