# frozen_string_literal: true

require_relative "../yaml/located_document"
require_relative "blacklist_reading"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Osdeps
    # A user's autoproj/deb_blacklist.yml: a list of autoproj package names,
    # globs or /regex/ (or the package set's unanchored regular expressions,
    # BlacklistReading) whose Debian packages must not be used.
    module BlacklistFile
      Entry = Struct.new(:pattern, :location)

      module_function

      # Raises InvalidInput with file:line for anything malformed.
      def load(path)
        document = Yaml::LocatedDocument.load(path)
        raise InvalidInput, document.diagnostics unless document.ok?

        data = document.data
        return [] if data.nil?
        unless data.is_a?(Array)
          raise InvalidInput, [Diagnostic.error("wrong-type", "the blacklist must be a list of package names or patterns",
                                                location: document.location([]), hint: "write one `- name` per line")]
        end

        problems = []
        entries = data.each_with_index.filter_map do |item, index|
          location = document.location([index])
          unless item.is_a?(String)
            problems << Diagnostic.error("wrong-type", "a blacklist entry must be a name or a pattern", location: location)
            next
          end
          parsed = BlacklistReading.parse(item)
          if parsed.is_a?(ReleaseSpec::PackagePattern::Invalid)
            problems << Diagnostic.error(parsed.rule, parsed.message, location: location, hint: parsed.hint)
            next
          end
          Entry.new(parsed, location)
        end
        raise InvalidInput, problems unless problems.empty?

        entries
      end
    end
  end
end
