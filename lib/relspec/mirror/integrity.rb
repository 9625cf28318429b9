# frozen_string_literal: true

require "set"
require_relative "../apt/fetcher"
require_relative "../apt/repository"
require_relative "proof"

module Relspec
  module Mirror
    # The mirror's files against each other, as apt will read them (what
    # `relspec mirror verify` checks before its proofs): every file a
    # Release file lists is there with the listed size and SHA256 (its
    # signature checked with the mirror's key when it has one), nothing
    # under dists/ is unlisted, the forms of one Packages index (plain, .gz,
    # .xz) hold the same text, and no file in the pool is one that no index
    # names. (An index entry whose pool file is missing or damaged is the
    # other direction: Mirror.missing_files, per target.)
    class Integrity
      SIGNATURES = %w[Release InRelease Release.gpg].freeze
      PACKAGES = %r{\A(?<dir>.+)/Packages(?:\.gz|\.xz)?\z}

      # +repository+: the AptRepository of the mirror; +targets+: every
      # Target it holds; +key+: the path of its public key, or nil
      # (unsigned, trusted=yes).
      def initialize(repository, targets, key:)
        @repository = repository
        @targets = targets
        @reader = Apt::Repository.new(Apt::Fetcher.new(repository.dir), keyring: key, trusted: key.nil?)
      end

      # A Proof::Check named "files", its problems sorted.
      def check
        problems = []
        codenames = @targets.map(&:codename).uniq.sort
        listed = codenames.sum { |codename| dists(codename, problems) }
        problems.concat(foreign_distributions(codenames))
        pool = files_below("pool")
        named = @targets.flat_map { |target| @repository.index(target).binaries.map(&:filename) }.to_set
        problems.concat((pool.to_set - named).sort.map { |path| "#{path} is in the pool but no index names it" })
        Proof::Check.new(name: "files", status: problems.empty? ? "passed" : "failed", problems: problems.freeze,
                         detail: "#{listed} index files checked against their Release file (size, SHA256), " \
                                 "#{pool.size} pool files against the indices").freeze
      end

      private

      # The problems of dists/+codename+ into +problems+; how many files its
      # Release file lists.
      def dists(codename, problems)
        release = @reader.release(codename)
        texts = release.checksums.keys.sort.to_h { |path| [path, text(codename, path, problems)] }
        problems.concat(disagreements(codename, texts))
        unlisted = files_below("dists/#{codename}").reject do |path|
          relative = path.delete_prefix("dists/#{codename}/")
          SIGNATURES.include?(relative) || release.checksum(relative)
        end
        problems.concat(unlisted.map { |path| "#{path} is not listed in the Release file" })
        release.checksums.size
      rescue Apt::Repository::Error => e
        problems << relative(e.message)
        0
      end

      def text(codename, path, problems)
        @reader.listed_text(codename, path)
      rescue Apt::Repository::Error => e
        problems << relative(e.message)
        nil
      end

      # The forms of one Packages index that do not hold the text of the
      # first (the plain one when it is listed), with the packages only one
      # of them has: apt reads one form, the checks another.
      def disagreements(codename, texts)
        forms = texts.select { |path, text| text && PACKAGES.match?(path) }
        forms.group_by { |path, _| path[PACKAGES, :dir] }.flat_map do |_, group|
          (first_path, first), *others = group.sort_by { |path, _| path.length }
          others.reject { |_, text| text == first }.map do |path, text|
            "dists/#{codename}/#{path} does not hold the packages of #{File.basename(first_path)}" \
              "#{difference(names(first), names(text))}"
          end
        end
      end

      def names(text)
        text.scan(/^Package:[ \t]*(\S+)/).flatten.to_set
      end

      def difference(expected, got)
        parts = []
        parts << "without #{(expected - got).sort.join(', ')}" unless (expected - got).empty?
        parts << "with #{(got - expected).sort.join(', ')}" unless (got - expected).empty?
        parts.empty? ? " (the same names, other fields)" : " (#{parts.join('; ')})"
      end

      # Distributions in dists/ that are no target's: apt would read them
      # if a machine named them, and no check here has.
      def foreign_distributions(codenames)
        Dir.children(File.join(@repository.dir, "dists")).sort.reject { |name| codenames.include?(name) }
           .map { |name| "dists/#{name} is the distribution of no target of mirror.yml" }
      rescue Errno::ENOENT
        ["dists/ is missing"]
      end

      # The files below +folder+ of the mirror, as paths relative to it.
      def files_below(folder)
        base = File.join(@repository.dir, folder)
        Dir.glob("**/*", File::FNM_DOTMATCH, base: base).select { |path| File.file?(File.join(base, path)) }
           .map { |path| "#{folder}/#{path}" }.sort
      end

      # The mirror's messages name its files from its own folder: the same
      # mirror gives the same report wherever it is mounted.
      def relative(message)
        message.gsub("#{@repository.dir}/", "")
      end
    end
  end
end
