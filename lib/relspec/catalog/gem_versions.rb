# frozen_string_literal: true

require_relative "../apt/fetcher"
require_relative "../error"

module Relspec
  class Catalog
    # The released versions of a gem in a spec's gem_source, to pick one
    # from when a gem osdep is packaged without a `gems:` entry:
    #
    # - a folder: the names of its <name>-<version>.gem files;
    # - a RubyGems-style server: its compact index, `<url>/info/<name>`
    #   (what rubygems.org serves to Bundler: one line per version,
    #   "1.2.0 dep:>= 1|checksum:…", and "1.2.0-java …" for platform gems).
    #
    # Platform gems and prereleases are left out: the package is made from
    # the plain gem, and a prerelease is only taken when `gems:` names it.
    # The compact index also says which Ruby each version needs ("ruby:>=
    # 3.2"): a hint that spares downloading a .gem whose Ruby does not fit
    # (the .gem's own gemspec decides).
    class GemVersions
      # Raised when the listing cannot be read; the message names its URL.
      class Problem < Relspec::Error; end

      # A compact index of a gem with a very long history (aws-sdk-core) is
      # a few hundred kB; what is larger is not one.
      MAX_BYTES = 8 * 1024 * 1024
      # A compact index line's first field: a gem version, maybe -platform.
      INDEX_VERSION = /\A[0-9][0-9A-Za-z.]*(-[A-Za-z0-9_.-]+)?\z/

      # +source+: gem_source as written; +base_dir+: where a relative
      # folder starts.
      def initialize(source, base_dir:, timeout: 10)
        @source = source.chomp("/")
        @base_dir = base_dir
        @fetcher = Apt::Fetcher.new(@source, timeout: timeout)
        @listed = {}
        @rubies = {}
      end

      def where
        @fetcher.remote? ? "#{@source}/info/<name>" : @source
      end

      def folder?
        !@fetcher.remote?
      end

      # Gem::Versions of +name+, highest first; [] when the source has none.
      # Each name is listed once per run.
      def of(name)
        @listed[name] ||= (@fetcher.remote? ? from_index(name) : from_folder(name)).uniq.sort.reverse.freeze
      end

      # The Gem::Requirement on Ruby the compact index gives for +name+
      # +version+ (listed by #of first), nil when it gives none (a folder
      # has no index) or one RubyGems cannot read.
      def required_ruby(name, version)
        of(name)
        @rubies.fetch(name, {})[Gem::Version.new(version)]
      end

      private

      def from_folder(name)
        folder = File.expand_path(@source.delete_prefix("file://"), @base_dir)
        pattern = /\A#{Regexp.escape(name)}-([0-9][^-]*)\.gem\z/
        Dir.children(folder).filter_map { |file| release(file[pattern, 1]) }
      rescue Errno::ENOENT, Errno::ENOTDIR
        raise Problem, "gem_source #{@source} is not a folder"
      end

      def from_index(name)
        text = @fetcher.fetch("info/#{name}", max_bytes: MAX_BYTES)
        return [] unless text

        pairs = index_versions(text.force_encoding(Encoding::UTF_8), "#{@source}/info/#{name}")
        @rubies[name] = pairs.select(&:last).to_h.freeze
        pairs.map(&:first)
      rescue Apt::Fetcher::Failure => e
        raise Problem, "cannot list the versions of gem #{name}: #{e.message}"
      end

      # The versions of a compact index, every line checked: a page that is
      # not one (a proxy's HTML, a truncated or binary answer) is a Problem
      # naming the URL and line, never "this gem has no versions".
      def index_versions(text, url)
        raise Problem, "#{url}: not a compact index (not UTF-8 text)" unless text.valid_encoding?

        text.each_line.with_index(1).filter_map do |line, number|
          next if number == 1 && line.chomp == "---"

          version, rest = line.chomp.split(" ", 2)
          unless version&.match?(INDEX_VERSION) && rest&.include?("|") && line.end_with?("\n")
            raise Problem, "#{url}:#{number}: not a compact index line (\"VERSION DEPENDENCIES|checksum:SHA256\"): " \
                           "#{line.chomp[0, 60].inspect}"
          end
          (found = release(version)) && [found, ruby_of(rest)]
        end
      end

      # "…|checksum:…,ruby:>= 2.7&< 4,…": the requirement of the ruby: field.
      def ruby_of(rest)
        field = rest.split("|", 2).last.split(",").find { |item| item.start_with?("ruby:") }
        field && Gem::Requirement.new(*field.delete_prefix("ruby:").split("&").map(&:strip))
      rescue Gem::Requirement::BadRequirementError
        nil
      end

      # A plain release version, or nil (platform, prerelease, not a version).
      def release(text)
        return nil unless text && !text.include?("-") && Gem::Version.correct?(text)

        version = Gem::Version.new(text)
        version.prerelease? ? nil : version
      end
    end
  end
end
