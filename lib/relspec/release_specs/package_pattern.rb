# frozen_string_literal: true

require_relative "names"
require_relative "../diagnostic"

module Relspec
  module ReleaseSpec
    # What a blacklist entry matches: an exact package name, a glob (`*` stays
    # inside one path segment, `**` crosses segments) or a /regex/.
    class PackagePattern
      # A problem with how a pattern is written; the caller adds the location.
      Invalid = Struct.new(:rule, :message, :hint, keyword_init: true) do
        # The problem as an error at +location+; +rule+ renames it for keys
        # other than the blacklist that take the same patterns.
        def diagnostic(location, rule: self.rule)
          Diagnostic.error(rule, message, location: location, hint: hint)
        end
      end

      GLOB_SEGMENT = /\A(\*\*|[A-Za-z0-9_.+\-*]+)\z/

      attr_reader :source, :kind

      # Returns a PackagePattern, or an Invalid describing why +source+ can never match.
      def self.parse(source)
        if source.start_with?("/") && source.end_with?("/") && source.size > 1
          parse_regex(source)
        elsif source.include?("*")
          parse_glob(source)
        elsif Names.package?(source)
          new(source, :exact, nil)
        else
          exact_problem(source)
        end
      end

      def self.parse_regex(source)
        body = source[1..-2]
        return Invalid.new(rule: "blacklist-regex", message: "empty regular expression //") if body.empty?

        new(source, :regex, Regexp.new(body))
      rescue RegexpError => e
        Invalid.new(rule: "blacklist-regex", message: "invalid regular expression #{source}: #{e.message}",
                    hint: "escape special characters with \\ or write the name without slashes")
      end

      def self.parse_glob(source)
        segments = source.split("/", -1)
        bad = segments.find { |segment| !GLOB_SEGMENT.match?(segment) || (segment != "**" && segment.include?("**")) }
        if bad
          return Invalid.new(rule: "blacklist-glob",
                             message: "glob #{source.inspect} cannot match any package name",
                             hint: glob_hint(bad))
        end

        new(source, :glob, glob_regexp(segments))
      end

      def self.glob_hint(segment)
        if segment.empty?
          "package names have no empty path segments: remove the extra or trailing \"/\""
        elsif segment.include?("**")
          "\"**\" must be a whole path segment, as in \"drivers/**\""
        else
          "package names use only letters, digits and _ . + - between slashes"
        end
      end

      def self.glob_regexp(segments)
        parts = segments.map do |segment|
          next ".*" if segment == "**"

          segment.split(/(\*)/).map { |piece| piece == "*" ? "[^/]*" : Regexp.escape(piece) }.join
        end
        Regexp.new("\\A#{parts.join('/')}\\z")
      end

      def self.exact_problem(source)
        if source.start_with?("/")
          Invalid.new(rule: "blacklist-regex", message: "#{source.inspect} starts like a /regex/ but does not end with \"/\"",
                      hint: "write /pattern/ for a regular expression")
        else
          bad = source.split("/", -1).find { |segment| !Names::PACKAGE.match?(segment) }
          Invalid.new(rule: "package-name", message: "#{source.inspect} is not a package name and cannot match any",
                      hint: glob_hint(bad.to_s))
        end
      end

      private_class_method :new, :parse_regex, :parse_glob, :glob_hint, :glob_regexp, :exact_problem

      def initialize(source, kind, regexp)
        @source = source
        @kind = kind
        @regexp = regexp
        freeze
      end

      def match?(package_name)
        kind == :exact ? package_name == source : @regexp.match?(package_name)
      end

      def to_s
        source
      end
    end
  end
end
