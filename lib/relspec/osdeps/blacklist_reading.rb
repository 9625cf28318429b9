# frozen_string_literal: true

require_relative "../release_specs/package_pattern"

module Relspec
  module Osdeps
    # One deb_blacklist.yml entry read both ways users write them: relspec's
    # forms (exact name, glob, /regex/) and the rock-osdeps package set's
    # (an entry with none of `+*{}(),;$` is an exact name, anything else an
    # unanchored regular expression). Users have files written for the
    # package set, so an entry relspec's forms cannot read takes the package
    # set's reading; where both read it and match different packages, the
    # entry disables what either matches (building a package from source is
    # never wrong, using a binary the user meant to replace is) and the
    # caller warns.
    class BlacklistReading
      # The package set's test for "this entry is a plain name".
      PLAIN = /\A[^+*{}(),;$]+\z/

      attr_reader :source, :relspec, :package_set

      # Returns a BlacklistReading, or the PackagePattern::Invalid of
      # relspec's reading when neither reading can match anything.
      def self.parse(source)
        relspec = ReleaseSpec::PackagePattern.parse(source)
        relspec = nil if relspec.is_a?(ReleaseSpec::PackagePattern::Invalid) && (invalid = relspec)
        package_set = package_set_regexp(source)
        return invalid if relspec.nil? && !package_set.is_a?(Regexp)

        new(source, relspec, package_set)
      end

      # The package set's reading: the name itself, or a Regexp; nil when
      # the package set cannot compile it (it would stop with an error).
      def self.package_set_regexp(source)
        return source if PLAIN.match?(source)

        quietly { Regexp.new(source) }
      rescue RegexpError
        nil
      end

      # Ruby warns on stderr about redundant repeats (`gui/**` read as a
      # regex), which are legal and common in globs.
      def self.quietly
        verbose = $VERBOSE
        $VERBOSE = nil
        yield
      ensure
        $VERBOSE = verbose
      end

      private_class_method :new, :package_set_regexp, :quietly

      def initialize(source, relspec, package_set)
        @source = source
        @relspec = relspec
        @package_set = package_set
        freeze
      end

      def match?(name)
        relspec_match?(name) || package_set_match?(name)
      end

      # Why the two readings of the entry differ on +names+ (the release's
      # packages), or nil when they match the same ones.
      def difference_note(names)
        return "the rock-osdeps package set cannot read it (not a valid regular expression)" if package_set.nil?

        ours = names.select { |name| relspec_match?(name) }
        theirs = names.select { |name| package_set_match?(name) }
        return nil if ours == theirs

        ours_kind = if relspec
                      "a #{relspec.kind == :exact ? 'name' : relspec.kind}"
                    else
                      "nothing it can read"
                    end
        theirs_kind = package_set.is_a?(Regexp) ? "an unanchored regular expression" : "a name"
        "relspec reads it as #{ours_kind} (#{listing(ours)}), the rock-osdeps package set as #{theirs_kind} " \
          "(#{listing(theirs)}): both are disabled"
      end

      def to_s
        source
      end

      private

      def listing(names)
        names.empty? ? "matches nothing" : names.join(", ")
      end

      def relspec_match?(name)
        !relspec.nil? && relspec.match?(name)
      end

      def package_set_match?(name)
        package_set.is_a?(Regexp) ? package_set.match?(name) : package_set == name
      end
    end
  end
end
