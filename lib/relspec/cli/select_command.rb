# frozen_string_literal: true

require_relative "../osdeps"
require_relative "../printable"

module Relspec
  module CLI
    # `relspec osdeps select`: runs Osdeps.select (Osdeps::UserSelection) with
    # the options and says what it did.
    class SelectCommand
      def initialize(options, err:)
        @options = options
        @err = err
      end

      def call
        release = @options[:release]
        result = Osdeps.select(
          release: release, arch: @options[:arch], os: @options[:os], data: @options[:data],
          blacklist: @options[:blacklist], index: @options[:index], trusted: @options[:trusted],
          keyring: @options[:keyring], output: @options[:output], timeout: @options[:timeout] || 10,
          differs: lambda do |entry, note|
            @err.puts("#{entry.location}: warning[blacklist-reading]: #{entry.pattern.source.inspect}: #{note}")
          end,
          unmatched: lambda do |entry|
            @err.puts("#{entry.location}: warning[unmatched-blacklist]: #{entry.pattern.source.inspect} matches no " \
                      "package of #{release}")
          end
        )
        selection = result.selection
        @err.puts("#{selection.active.size} packages active, #{selection.inactive.size} disabled (#{Printable.text(result.path)})")
      end
    end
  end
end
