# frozen_string_literal: true

require "digest"
require_relative "../builder/abi_dumper"
require_relative "published_dumps"

module Relspec
  module Abi
    # A repository's ABI index (PublishedDumps) that cannot be read, made
    # again from what the folder holds, so that a damaged index never stops
    # a publish halfway (issue 46 case 7). The folder's files are untrusted:
    # a dump file (<source>/<library>.abi.xml.gz, a plain file) is listed
    # again only when a build record vouches for it (the same source, file
    # name and SHA256 in build-results.yml), with that record's package and
    # version; every other file is left out, and named.
    #
    # +dumps+: the PublishedDumps made again; +left_out+: the files not
    # vouched for (full paths, sorted); +problem+: why the index could not
    # be read (the reader's message).
    RebuiltDumps = Struct.new(:dumps, :left_out, :problem, keyword_init: true)

    # Its making.
    class RebuiltDumps
      # The dumps of +target+ in +repository+ that +records+
      # (Builder::BuildResults::Record, built) vouch for; +problem+ as above.
      def self.of(repository, target, records, problem:)
        dir = PublishedDumps.dir(repository, target)
        vouched = records.flat_map do |record|
          record.files.select { |file| Builder::AbiDumper.library_of(file.name) }
                .map { |file| [[record.source, File.basename(file.name), file.sha256], record] }
        end.to_h
        kept, left_out = present(dir).partition do |path|
          vouched.key?(key(path, Digest::SHA256.file(path).hexdigest))
        end
        entries = kept.map do |path|
          sha256 = Digest::SHA256.file(path).hexdigest
          record = vouched.fetch(key(path, sha256))
          PublishedDumps::Entry.new(package: record.package, source: record.source, version: record.version,
                                    library: Builder::AbiDumper.library_of(path), file: path, sha256: sha256).freeze
        end
        new(dumps: PublishedDumps.new(dir, entries), left_out: left_out.freeze, problem: problem).freeze
      end

      # The dump files below +dir+: plain files one folder down (a link is
      # never followed, and never listed).
      def self.present(dir)
        Dir.glob(File.join(dir, "*", "*#{Builder::AbiDumper::SUFFIX}")).sort.select do |path|
          File.file?(path) && !File.symlink?(path) && !File.symlink?(File.dirname(path))
        end
      end

      def self.key(path, sha256)
        [File.basename(File.dirname(path)), File.basename(path), sha256]
      end
      private_class_method :present, :key
    end
  end
end
