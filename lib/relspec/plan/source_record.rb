# frozen_string_literal: true

module Relspec
  module Plan
    # Where a package's source comes from, as the lock records it (its
    # `packages:` section) and as `relspec diff` compares it. The one place
    # that defines the record's fields: the planner fills them, the lock
    # writes them in this order, LockParser accepts exactly these keys, each
    # text, and the diff compares every one. A new field is a new member here.
    # +sha256+: an archive import's checksum (Catalog::ArchiveImport).
    SourceRecord = Struct.new(:url, :commit, :sha256, :commit_time, :version, :tag, :branch, keyword_init: true) do
      # The keys as the lock writes them.
      def self.fields
        members.map(&:to_s)
      end

      # A frozen record from a lock's mapping (string keys) or a record.
      def self.from(value)
        return value.frozen? ? value : value.dup.freeze if value.is_a?(self)

        new(**value.to_h { |key, text| [key.to_sym, text.is_a?(String) ? -text : text] }).freeze
      end

      # Plain data in the lock's order, without the fields not known.
      def to_h
        self.class.members.to_h { |member| [member.to_s, self[member]] }.compact
      end

      # field => [before, after] for every field that differs from +other+.
      def changes(other)
        self.class.members.filter_map do |member|
          [member.to_s, [self[member], other[member]]] unless self[member] == other[member]
        end.to_h
      end
    end
  end
end
