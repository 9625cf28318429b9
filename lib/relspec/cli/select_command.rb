# frozen_string_literal: true

require_relative "../osdeps/operating_system"
require_relative "../osdeps/release_data"
require_relative "../osdeps/blacklist_file"
require_relative "../osdeps/index_sources"
require_relative "../osdeps/selection"
require_relative "../yaml/writer"
require_relative "../atomic_file"

module Relspec
  module CLI
    # `relspec osdeps select`: the user-side selection. Everything is read
    # and computed before anything is written, and both files are written
    # with rename, so a bad blacklist leaves the previous files untouched.
    class SelectCommand
      def initialize(options, err:)
        @options = options
        @err = err
      end

      def call
        os = parse_os
        mapping = resolve(Osdeps::ReleaseData.new(@options[:data]).merged(@options[:release], @options[:arch]), os)
        blacklist = @options[:blacklist] ? Osdeps::BlacklistFile.load(@options[:blacklist]) : []
        indices = Osdeps::IndexSources.load(@options[:index], codename: codename(os), arch: @options[:arch],
                                                              trusted: @options[:trusted], keyring: @options[:keyring])
        selection = Osdeps::Selection.new(mapping, indices, blacklist)
        blacklist.each do |entry|
          note = entry.pattern.difference_note(mapping.keys.sort)
          @err.puts("#{entry.location}: warning[blacklist-reading]: #{entry.pattern.source.inspect}: #{note}") if note
        end
        selection.unmatched.each do |entry|
          @err.puts("#{entry.location}: warning[unmatched-blacklist]: #{entry.pattern.source.inspect} matches no package " \
                    "of #{@options[:release]}")
        end
        write(selection)
      end

      private

      def parse_os
        Osdeps::OperatingSystem.parse(@options[:os])
      end

      # The user's codename, to read repository URLs with.
      def codename(os)
        os.versions.find { |version| version.match?(/\A[a-z]+\z/) && version != "default" }
      end

      def resolve(entries, os)
        entries.filter_map { |package, entry| (deb = os.resolve(entry)) && [package, deb] }.to_h
      end

      def write(selection)
        osdeps = selection.active.transform_values { |deb| { "default" => deb } }
        FileUtils.mkdir_p(@options[:output])
        AtomicFile.write(File.join(@options[:output], "rock-osdeps.osdeps"), Yaml::Writer.dump(osdeps))
        AtomicFile.write(File.join(@options[:output], "rock-osdeps.inactive"), Yaml::Writer.dump(selection.inactive))
        @err.puts("#{osdeps.size} packages active, #{selection.inactive.size} disabled " \
                  "(#{File.join(@options[:output], 'rock-osdeps.osdeps')})")
      end
    end
  end
end
