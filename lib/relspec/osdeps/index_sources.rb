# frozen_string_literal: true

require "open3"
require "zlib"
require_relative "../apt/repository"
require_relative "../apt/package_index"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../printable"

module Relspec
  module Osdeps
    # The Packages indices `osdeps select` computes reverse dependencies
    # from: Packages files (plain, .gz, .xz, or apt's .lz4 lists) or apt
    # repository URLs read for the user's codename and architecture.
    module IndexSources
      module_function

      def load(sources, codename:, arch:, trusted:, keyring:, timeout: 10)
        sources.flat_map do |source|
          if source.match?(%r{\Ahttps?://})
            repository_indices(Apt::Repository.new(Apt::Fetcher.new(source, timeout: timeout), trusted: trusted, keyring: keyring),
                               codename, arch)
          else
            [Apt::PackageIndex.parse(read_file(source))]
          end
        rescue Apt::Repository::Error, Apt::Deb822::ParseError, Apt::PackageIndex::Invalid, ToolError, Zlib::Error, SystemCallError => e
          raise InvalidInput, [Diagnostic.error("index", "cannot read the index #{Printable.text(source)}: #{Printable.text(e.message)}",
                                                location: Location.file_only(source))]
        end
      end

      # The index of +arch+ and the binary-all apt reads beside it, if any.
      def repository_indices(repository, codename, arch)
        repository.index_architectures(codename, arch).map { |read| repository.packages(codename, read) }
      end

      def read_file(path)
        bytes = File.binread(path)
        case path
        when /\.gz\z/ then Zlib::GzipReader.zcat(StringIO.new(bytes)) # every member, as gzip -d reads them
        when /\.xz\z/ then decompress("xz", bytes)
        when /\.lz4\z/ then decompress("lz4cat", bytes)
        else bytes
        end.b
      end

      def decompress(tool, bytes)
        command = tool == "xz" ? %w[xz -dc] : [tool]
        out, err, status = Open3.capture3(*command, stdin_data: bytes, binmode: true)
        raise ToolError, "#{tool}: #{err.strip}" unless status.success?

        out
      end
    end
  end
end
