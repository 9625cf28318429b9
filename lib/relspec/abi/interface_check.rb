# frozen_string_literal: true

require_relative "interface_verdict"
require_relative "installed_files"
require_relative "../builder/abi_dumper"

module Relspec
  module Abi
    # Decides whether a package's new build changed the interface its
    # dependents build against (docs/abi.md, "Early cutoff"): every file it
    # installs byte-identical to the build it replaces, except shared
    # libraries, whose ABI dumps must be equal or only compatibly extended
    # (functions or variables added, nothing removed or changed; abidiff
    # reads the installed headers when both sides were unpacked). A file
    # added or removed, a link moved, a library without a dump on either
    # side: changed. Headers, pkg-config and CMake files, Ruby files,
    # generators, data and oroGen type registries (share/orogen/*.tlb) are
    # all files, compared by their bytes.
    class InterfaceCheck
      # One build's side: +files+ (InstalledFiles.of its .debs) and +dumps+
      # (library file name => path of its .abi.xml.gz).
      # +root+: a folder holding the installed files (the .debs unpacked),
      # whose headers tell abidiff which types users can see; nil when not
      # unpacked.
      Side = Struct.new(:version, :files, :dumps, :root, keyword_init: true) do
        # The side of a build at +version+ whose produced files are +paths+
        # (its .debs and its ABI dumps, as build-results.yml lists them);
        # +root+: an empty folder to unpack its non-debug .debs into, or nil.
        def self.of(version, paths, root: nil)
          dumps = paths.filter_map { |path| (library = Builder::AbiDumper.library_of(path)) && [library, path] }.to_h
          debs = paths.grep(/\.deb\z/)
          InstalledFiles.unpack(debs, root) if root
          new(version: version, files: InstalledFiles.of(debs), dumps: dumps.freeze, root: root).freeze
        end
      end

      # +compare+: called with (old dump, new dump, headers: [old root, new
      # root] or nil), returns a Verdict (Comparison.method(:compare)).
      def initialize(compare:)
        @compare = compare
      end

      # The InterfaceVerdict of +package+'s +new+ build (a Side) against
      # +old+, the build it replaces.
      def decide(package, old:, new:)
        paths = (old.files.keys | new.files.keys).sort
        evidence = paths.map { |path| compare_entry(path, old, new) }
        # nothing read is nothing proven: a side that installs nothing (no
        # .deb found) never keeps the dependents
        empty = { "old" => old, "new" => new }.select { |_, side| side.files.empty? }.keys
        evidence << evidence("", :bytes, :no_files, "the #{empty.join(' and ')} build installs nothing") unless empty.empty?
        InterfaceVerdict.of(package: package, version: new.version, against: old.version, evidence: evidence)
      end

      private

      def compare_entry(path, old, new)
        before = old.files[path]
        after = new.files[path]
        check = (after || before).kind == :library ? :abi : :bytes
        check = :link if (after || before).kind == :link
        return evidence(path, check, :added) unless before
        return evidence(path, check, :removed) unless after
        return evidence(path, check, :kind, "#{before.kind} -> #{after.kind}") unless before.kind == after.kind
        return evidence(path, check, :identical) if before.content == after.content
        return evidence(path, check, :differs) unless check == :abi

        library(path, old, new)
      end

      # A library whose bytes moved: its two dumps, compared.
      def library(path, old, new)
        name = File.basename(path)
        missing = { "old" => old.dumps[name], "new" => new.dumps[name] }.select { |_, dump| dump.nil? }.keys
        return evidence(path, :abi, :no_dump, "no ABI dump of the #{missing.join(' and ')} build") unless missing.empty?

        headers = old.root && new.root ? [old.root, new.root] : nil
        verdict = @compare.call(old.dumps[name], new.dumps[name], headers: headers)
        evidence(path, :abi, verdict.verdict.to_sym, verdict.summary.join("; "))
      end

      def evidence(path, check, outcome, detail = nil)
        InterfaceVerdict::Evidence.new(path: path, check: check, outcome: outcome, detail: detail)
      end
    end
  end
end
