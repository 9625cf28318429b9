# frozen_string_literal: true

require "open3"
require "tmpdir"
require "zlib"
require_relative "../error"
require_relative "verdict"
require_relative "../builder/abi_dumper"
require_relative "type_registry"

module Relspec
  module Abi
    # Compares two stored dumps (.abi.xml.gz) of one library with `abidiff`
    # (two type registries of a typekit with TypeRegistry):
    # the dumps are read, not the libraries, so nothing is extracted again
    # (docs/abi.md). abidiff's exit status is a bit field: 1 an error, 2 a
    # usage error (both a ToolError here), 4 an ABI change, 8 an
    # incompatible one.
    module Comparison
      ERROR_BITS = 3
      # Anything larger than this unpacked is not a dump relspec made.
      MAX_XML = 512 * 1024 * 1024

      module_function

      # The Verdict of +old+ against +new+ (paths of .abi.xml.gz files).
      # +headers+: [old folder, new folder] holding each build's installed
      # files: abidiff then leaves out changes of types no installed header
      # defines (a pimpl's private struct), which no user can name.
      def compare(old, new, headers: nil)
        [old, new].each { |path| raise ToolError, "the ABI dump #{path} is missing" unless File.file?(path) }
        Dir.mktmpdir("relspec-abidiff") do |dir|
          old_xml = unpack(old, File.join(dir, "old.xml"))
          new_xml = unpack(new, File.join(dir, "new.xml"))
          return registries(old_xml, old, new_xml, new) if Builder::AbiDumper.registry?(Builder::AbiDumper.library_of(old).to_s)

          dirs = headers ? ["--headers-dir1", headers.first, "--headers-dir2", headers.last] : []
          output, error, status = Open3.capture3("abidiff", "--no-show-locs", *dirs, old_xml, new_xml)
          code = status.exitstatus
          if code.nil? || code.anybits?(ERROR_BITS)
            raise ToolError, "abidiff #{old} #{new} failed (exit status #{code.inspect}): #{error.strip.lines.first&.strip}"
          end

          Verdict.of(code, output)
        end
      rescue Errno::ENOENT
        raise ToolError, "cannot run abidiff (is abigail-tools installed? bin/setup installs it)"
      end

      # Two oroGen type registries, compared type by type (TypeRegistry).
      def registries(old_xml, old, new_xml, new)
        TypeRegistry.read(old_xml, file: old).compare(TypeRegistry.read(new_xml, file: new))
      end

      def unpack(dump, to)
        File.open(to, "wb") do |file|
          Zlib::GzipReader.open(dump) do |gzip|
            while (chunk = gzip.read(1 << 20))
              file.write(chunk)
              raise ToolError, "#{dump} unpacks to more than #{MAX_XML} bytes: not an ABI dump" if file.size > MAX_XML
            end
          end
        end
        to
      rescue Zlib::Error => e
        raise ToolError, "#{dump} is not a gzip-compressed ABI dump: #{e.message}"
      end
    end
  end
end
