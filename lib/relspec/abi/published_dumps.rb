# frozen_string_literal: true

require "digest"
require "fileutils"
require "yaml"
require_relative "../atomic_file"
require_relative "../display_path"
require_relative "../error"
require_relative "../unlinked_path"
require_relative "../yaml/located_document"
require_relative "../yaml/field_reader"
require_relative "../builder/abi_dumper"

module Relspec
  module Abi
    # The ABI dumps a release's repository holds for one target, beside its
    # apt repository: <repository>/abi/<codename>-<arch>/index.yml lists each
    # dump (the autoproj package, its Debian source and version, the library,
    # the file below that folder and its SHA256); the dumps sit at
    # <source>/<library>.abi.xml.gz. `relspec publish` writes them, `relspec
    # abi` reads them strictly: the file comes from a repository, which may
    # be someone else's, so every field is checked and every path stays
    # inside the folder.
    class PublishedDumps
      FILE_NAME = "index.yml"
      FORMAT_KEY = "relspec_abi_dumps"
      FORMAT_VERSION = 1
      ENTRY_KEYS = %w[package source version library file sha256].freeze
      SHA256 = /\A[0-9a-f]{64}\z/
      HINT = "the ABI index is written by `relspec publish`: publish the release again"

      # One dump: +file+ the full path of the .abi.xml.gz.
      Entry = Struct.new(:package, :source, :version, :library, :file, :sha256, keyword_init: true)

      attr_reader :dir, :entries

      def self.dir(repository, target)
        File.join(repository, "abi", target.dir_name)
      end

      # The dumps of +target+ in +repository+; none when it has no index.
      def self.read(repository, target)
        dir = dir(repository, target)
        path = File.join(dir, FILE_NAME)
        return new(dir, []) unless File.file?(path)

        new(dir, Reader.new(Yaml::LocatedDocument.load(DisplayPath.of(path)), dir).entries)
      end

      # Copies the dumps of +records+ (Builder::BuildResults::Record, built,
      # in +target_dir+) into the repository and writes the index; true when
      # something changed. Dumps of sources not built now are kept (an
      # earlier publish of the same release): those of +current+, the index
      # as read before anything was published (or as made again,
      # RebuiltDumps).
      def self.write(repository, target, target_dir, records, current: read(repository, target))
        check(repository, target, records)
        dir = dir(repository, target)
        known = current.entries.to_h do |entry|
          [[entry.source, entry.library], entry.dup.tap { |kept| kept.file = entry.file.delete_prefix("#{dir}/") }]
        end
        records.each do |record|
          known.reject! { |(source, _), _| source == record.source }
          record.files.each do |file|
            library = Builder::AbiDumper.library_of(file.name) or next
            relative = File.join(record.source, File.basename(file.name))
            FileUtils.mkdir_p(File.join(dir, record.source))
            AtomicFile.write(File.join(dir, relative), File.binread(File.join(target_dir, file.name)))
            known[[record.source, library]] = Entry.new(package: record.package, source: record.source,
                                                        version: record.version, library: library,
                                                        file: relative, sha256: file.sha256).freeze
          end
        end
        index = File.join(dir, FILE_NAME)
        # a repository of packages without libraries gets no abi/ folder
        return false if known.empty? && !File.exist?(index)

        AtomicFile.update(index, render(known.values))
      end

      # Raises PublishError naming a symbolic link on the way to a file
      # #write of +records+ would write (abi/, the target's folder, its
      # index, a source's folder, a dump): through it publish would
      # overwrite the files of a folder it did not make. Publish asks
      # before it touches the repository.
      def self.check(repository, target, records)
        base = File.join("abi", target.dir_name)
        dumps = records.flat_map do |record|
          record.files.select { |file| Builder::AbiDumper.library_of(file.name) }
                .map { |file| File.join(base, record.source, File.basename(file.name)) }
        end
        why = "publish writes the ABI dumps only inside #{dir(repository, target)} and never through a link; " \
              "remove the link and publish again"
        [File.join(base, FILE_NAME), *dumps].each do |relative|
          UnlinkedPath.check(repository, relative, why: why, error: PublishError)
        end
      end

      def self.render(entries)
        rows = entries.sort_by { |entry| [entry.package, entry.library] }.map do |entry|
          ENTRY_KEYS.to_h { |key| [key, entry.public_send(key)] }
        end
        YAML.dump({ FORMAT_KEY => FORMAT_VERSION, "dumps" => rows })
      end

      def initialize(dir, entries)
        @dir = dir
        @entries = entries.freeze
        freeze
      end

      # The dumps of autoproj package +package+.
      def of(package)
        entries.select { |entry| entry.package == package }
      end

      # The strict reading of index.yml.
      class Reader
        attr_reader :entries

        def initialize(document, dir)
          @fields = Yaml::FieldReader.new(document, rule: "abi-index", what: "the ABI index", hint: HINT)
          data = @fields.root
          unless data[FORMAT_KEY] == FORMAT_VERSION
            @fields.fail_at([FORMAT_KEY], "unknown format #{data[FORMAT_KEY].inspect} (this relspec reads #{FORMAT_VERSION})")
          end
          @fields.known_keys(data, [], [FORMAT_KEY, "dumps"])
          @entries = @fields.list(data, ["dumps"], of: "dumps").each_with_index.map { |row, index| entry(row, index, dir) }
        end

        private

        def entry(row, index, dir)
          at = ["dumps", index]
          @fields.fail_at(at, "#{@fields.describe(at)} must be a mapping") unless row.is_a?(Hash)
          @fields.known_keys(row, at, ENTRY_KEYS)
          library = @fields.text(row, at + ["library"])
          @fields.fail_at(at + ["library"], "#{library.inspect} is not a shared library or type registry name") unless Builder::AbiDumper.dumped?(library)
          file = @fields.plain_path(row, at + ["file"])
          @fields.fail_at(at + ["file"], "#{file.inspect} is not a dump of #{library}") unless Builder::AbiDumper.library_of(file) == library
          sha256 = @fields.text(row, at + ["sha256"])
          @fields.fail_at(at + ["sha256"], "sha256 must be 64 lowercase hex digits") unless sha256.match?(SHA256)
          Entry.new(package: @fields.text(row, at + ["package"]), source: @fields.text(row, at + ["source"]),
                    version: @fields.text(row, at + ["version"]), library: library, file: File.join(dir, file),
                    sha256: sha256).freeze
        end
      end
    end
  end
end
