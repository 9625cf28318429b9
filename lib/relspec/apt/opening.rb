# frozen_string_literal: true

require_relative "repository"
require_relative "host_lists"

module Relspec
  module Apt
    # The one way a declared repository becomes something to read: a
    # repository entry (anything with +keyring+ and +trusted+) at one of its
    # locations, or a distribution's archive entry.
    module Opening
      module_function

      # +entry+ read at +location+ (a path or URL) as an Apt::Repository;
      # +fetcher_options+ go to its Fetcher (timeout).
      def repository(entry, location, fetcher_options: {}, cache: Cache.new(nil))
        Repository.new(Fetcher.new(location, **fetcher_options), keyring: entry.keyring, trusted: entry.trusted, cache: cache)
      end

      # A distribution's `archive:` entry: this machine's apt lists for
      # `host: true`, else its repository, relative paths against +base+.
      def archive(archive, base, fetcher_options: {}, cache: Cache.new(nil))
        return HostLists.new if archive.host?

        entry = archive.repository_entry(base)
        repository(entry, entry.location, fetcher_options: fetcher_options, cache: cache)
      end
    end
  end
end
