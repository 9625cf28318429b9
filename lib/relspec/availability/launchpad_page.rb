# frozen_string_literal: true

require "json"
require_relative "../error"

module Relspec
  module Availability
    # One page of a Launchpad collection (getPublishedBinaries), its shape
    # checked before anything reads it: a mapping with a list of entries,
    # each a mapping whose binary_package_name is text, and a
    # next_collection_link that is absent or an http(s) URL. A server that
    # answers something else (a proxy's page, a truncated body, another
    # API) is a Failure naming the URL and the field, never a TypeError.
    # Kept apart from the HTTP loop (LaunchpadClient): this is about what
    # the bytes mean, not how they arrive.
    class LaunchpadPage
      attr_reader :entries, :next_link

      # +failure+: the error class to raise (LaunchpadClient::Failure).
      def self.parse(body, url, failure:)
        data = JSON.parse(body)
      rescue JSON::ParserError => e
        raise failure, "Launchpad: #{url}: the answer is not JSON (#{e.message[0, 80]})"
      else
        new(data, url, failure)
      end

      def initialize(data, url, failure)
        @url = url
        @failure = failure
        refuse("the answer is not a collection (a JSON object with entries)") unless data.is_a?(Hash) && data.key?("entries")
        @entries = checked_entries(data["entries"]).freeze
        @next_link = checked_link(data["next_collection_link"])
        freeze
      end

      private

      def checked_entries(entries)
        refuse("entries is #{kind(entries)}, not a list") unless entries.is_a?(Array)
        entries.each_with_index do |entry, index|
          refuse("entries[#{index}] is #{kind(entry)}, not an object") unless entry.is_a?(Hash)
          name = entry["binary_package_name"]
          refuse("entries[#{index}].binary_package_name is #{kind(name)}, not text") unless name.is_a?(String)
        end
      end

      def checked_link(link)
        return nil if link.nil?
        return link if link.is_a?(String) && link.match?(%r{\Ahttps?://}i)

        refuse("next_collection_link is #{link.is_a?(String) ? link[0, 80].inspect : kind(link)}, not an http(s) URL")
      end

      def kind(value)
        case value
        when nil then "null"
        when Hash then "an object"
        when Array then "a list"
        when String then "text"
        when true, false then "a boolean"
        else "a number"
        end
      end

      def refuse(message)
        raise @failure, "Launchpad: #{@url}: #{message}"
      end
    end
  end
end
