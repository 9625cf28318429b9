# frozen_string_literal: true

require_relative "schema"
require_relative "value_kind"
require_relative "../diagnostic"
require_relative "../suggestion"

module Relspec
  module ReleaseSpec
    # Runs the schemas over one located document and turns dry-schema's
    # messages into diagnostics that point at the offending key or value.
    class SchemaCheck
      Result = Struct.new(:diagnostics, :broken_keys, keyword_init: true)

      ENTRY_MAPPINGS = {
        "pins" => Schema::PIN, "external" => Schema::EXTERNAL, "distributions" => Schema::DISTRIBUTION
      }.freeze

      MISSING_HINTS = {
        "release" => "a spec starts with `release: <name>`, the name of its file",
        "match" => "each entry needs match: (a package name, a glob like drivers/* or a /regex/)",
        "reason" => "say why the release does without it, e.g. reason: needs qt4, which bookworm lacks",
        "type" => "type is ubuntu or debian",
        "labels" => "labels are the names autoproj knows the distribution by, e.g. [13, trixie, default]"
      }.freeze

      def self.call(document)
        new(document).call
      end

      def initialize(document)
        @document = document
        @diagnostics = []
      end

      def call
        data = @document.data
        unless data.is_a?(Hash)
          return Result.new(diagnostics: [root_problem(data)], broken_keys: Schema.keys(Schema::RELEASE))
        end

        apply(Schema::RELEASE, shallow(data), [])
        check_entries(data)
        Result.new(diagnostics: @diagnostics.map(&:first), broken_keys: @diagnostics.map(&:last).compact.uniq)
      end

      private

      def root_problem(data)
        location = @document.location([])
        if data.nil?
          Diagnostic.error("missing-key", "the file is empty", location: location,
                                                               hint: "a spec starts with `release: <name>`")
        else
          Diagnostic.error("wrong-type", "a release spec must be a mapping of keys to values, found #{ValueKind.of(data)}",
                           location: location, hint: "a spec starts with `release: <name>`")
        end
      end

      # Mappings checked entry by entry are passed to the top schema empty, so
      # that only their type is checked there.
      def shallow(data)
        data.to_h do |key, value|
          if Schema::CHECKED_SEPARATELY.include?(key) && value.is_a?(Hash)
            [key, {}]
          elsif key == "blacklist" && value.is_a?(Array)
            [key, value.map { |entry| entry.is_a?(Hash) ? {} : flat(entry) }]
          elsif key == "leave_out" && value.is_a?(Array)
            [key, value.map { |entry| entry.is_a?(Hash) ? {} : entry }]
          elsif key == "select" && value.is_a?(Array)
            [key, value.map { |entry| flat(entry) }]
          else
            [key, value]
          end
        end
      end

      # With validate_keys, dry-schema reads a list inside a list of names as
      # a mapping and reports a key path that names nothing (`select: [[x]]`
      # passed). Lists and mappings become nil, which it reports as a wrong
      # type at the entry itself; the message still shows the real value.
      def flat(entry)
        entry.is_a?(Array) || entry.is_a?(Hash) ? nil : entry
      end

      def check_entries(data)
        check_blacklist(data["blacklist"])
        check_list("leave_out", Schema::LEAVE_OUT_ENTRY, data["leave_out"])
        apply(Schema::OWN_REPOSITORY, data["repository"], ["repository"]) if data["repository"].is_a?(Hash)
        apply(Schema::EARLY_CUTOFF, data["early_cutoff"], ["early_cutoff"]) if data["early_cutoff"].is_a?(Hash)
        ENTRY_MAPPINGS.each do |key, schema|
          next unless data[key].is_a?(Hash)

          data[key].each do |name, value|
            apply(schema, value, [key, name])
          end
        end
        (data["distributions"].is_a?(Hash) ? data["distributions"] : {}).each do |codename, definition|
          archive = definition.is_a?(Hash) && definition["archive"]
          apply(Schema::ARCHIVE, archive, ["distributions", codename, "archive"]) if archive.is_a?(Hash)
        end
        check_text_values("gems", data["gems"])
      end

      def check_blacklist(entries)
        return unless entries.is_a?(Array)

        entries.each_with_index do |entry, index|
          apply(Schema::BLACKLIST_ENTRY, entry, ["blacklist", index]) if entry.is_a?(Hash)
        end
      end

      def check_list(key, schema, entries)
        return unless entries.is_a?(Array)

        entries.each_with_index { |entry, index| apply(schema, entry, [key, index]) if entry.is_a?(Hash) }
      end

      def check_text_values(key, mapping)
        return unless mapping.is_a?(Hash)

        mapping.each do |name, value|
          next if value.is_a?(String) && !value.empty?

          report("wrong-type", "\"#{name}\" must be a version string, found #{ValueKind.of(value)}",
                 @document.location([key, name]), key, hint: "write it as #{name}: \"1.2.3\"")
        end
      end

      def apply(schema, value, prefix)
        unless value.is_a?(Hash)
          report("wrong-type", "#{label(prefix)} must be a mapping, found #{ValueKind.of(value)}",
                 @document.location(prefix), prefix.first)
          return
        end

        schema.call(value).errors.each { |message| translate(schema, message, prefix) }
      end

      def translate(schema, message, prefix)
        path = prefix + message.path.map { |part| part.is_a?(Symbol) ? part.to_s : part }
        top = path.first
        case predicate(message)
        when :unexpected_key then unknown_key(schema, path[0..prefix.size], top)
        when :key? then report("missing-key", "missing required key \"#{path.last}\"",
                               @document.location(path[0..-2]), top, hint: MISSING_HINTS[path.last])
        when :filled? then report("empty-value", "#{label(path)} must not be empty", @document.location(path), top)
        when :included_in? then report("invalid-value", "#{label(path)} #{message.text}, found #{value_at(path).inspect}",
                                       @document.location(path), top)
        else
          report("wrong-type", "#{label(path)} #{wording(message.to_s)}, found #{ValueKind.of(value_at(path))}",
                 @document.location(path), top)
        end
      end

      # Schemas are flat, so the unknown key is the first one below +prefix+;
      # dry-schema also reports keys nested in values of allowed keys, which
      # the entry checks handle.
      def unknown_key(schema, path, top)
        allowed = Schema.keys(schema)
        return if allowed.include?(path.last)

        hint = Suggestion.hint(path.last, allowed) || "allowed here: #{allowed.join(', ')}"
        report("unknown-key", "unknown key \"#{path.last}\"", @document.key_location(path), top, hint: hint)
      end

      def predicate(message)
        message.respond_to?(:predicate) ? message.predicate : nil
      end

      def value_at(path)
        path.reduce(@document.data) { |node, part| node.is_a?(Hash) || node.is_a?(Array) ? node[part] : nil }
      end

      def label(path)
        last_key = path.reverse.find { |part| part.is_a?(String) }
        index = path.last.is_a?(Integer) ? " entry #{path.last + 1}" : ""
        "\"#{last_key}\"#{index}"
      end

      def wording(text)
        text.gsub("must be a hash", "must be a mapping").gsub("must be an array", "must be a list")
            .gsub("must be boolean", "must be true or false")
      end

      def report(rule, message, location, top_key, hint: nil)
        diagnostic = Diagnostic.error(rule, message, location: location, hint: hint)
        @diagnostics << [diagnostic, top_key] unless @diagnostics.any? { |known, _| known == diagnostic }
      end
    end
  end
end
