# frozen_string_literal: true

module Relspec
  class Catalog
    # The OS dependencies of one package resolved for one distribution, as
    # autoproj's osdeps resolve them: Debian packages, gems, names the
    # distribution does not need (ignore), names it cannot provide
    # (nonexistent), names the osdeps files define for other systems only
    # (other_os: autoproj's WRONG_OS, unavailable here as nonexistent ones
    # are) and names no osdeps file defines at all (unresolved);
    # optional ones the distribution cannot provide are left out, as
    # autoproj leaves them out, and listed (optional_missing) for plan.
    class OsDependencies
      FIELDS = %w[apt gems ignored nonexistent other_os unresolved optional_missing].freeze

      attr_reader(*FIELDS)

      def self.build(**lists)
        new(**FIELDS.to_h { |field| [field.to_sym, lists.fetch(field.to_sym, [])] })
      end

      def self.from_h(hash)
        build(**FIELDS.to_h { |field| [field.to_sym, hash.fetch(field, [])] })
      end

      def initialize(apt:, gems:, ignored:, nonexistent:, unresolved:, other_os: [], optional_missing: [])
        @apt = apt.uniq.sort.freeze
        @gems = gems.uniq.sort.freeze
        @ignored = ignored.uniq.sort.freeze
        @nonexistent = nonexistent.uniq.sort.freeze
        @other_os = other_os.uniq.sort.freeze
        @unresolved = unresolved.uniq.sort.freeze
        @optional_missing = optional_missing.uniq.sort.freeze
        freeze
      end

      EMPTY = build

      def empty?
        FIELDS.all? { |field| public_send(field).empty? }
      end

      def ==(other)
        other.is_a?(OsDependencies) && to_h == other.to_h
      end

      def to_h
        FIELDS.to_h { |field| [field, public_send(field)] }.reject { |_field, names| names.empty? }
      end
    end
  end
end
