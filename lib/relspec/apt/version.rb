# frozen_string_literal: true

module Relspec
  module Apt
    # Debian version numbers ([epoch:]upstream[-revision]) compared exactly as
    # dpkg compares them (deb-version(7)): epochs numerically, then upstream
    # and revision by alternating non-digit and digit runs, where `~` sorts
    # before everything (even the end of the string), letters before other
    # characters, and digit runs compare numerically.
    class Version
      include Comparable

      FORMAT = /\A(?:(\d+):)?([A-Za-z0-9.+~:-]*?)(?:-([A-Za-z0-9.+~]*))?\z/
      # deb-version(5): the upstream part starts with a digit; a colon only
      # with an epoch, a hyphen only with a revision.
      VALID = /\A(?:\d+:[0-9][A-Za-z0-9.+~:-]*|[0-9][A-Za-z0-9.+~-]*)\z/

      # Is +text+ a Debian version dpkg accepts? (Cheap: no object made.)
      def self.valid?(text)
        text = text.strip
        return false unless VALID.match?(text)

        match = FORMAT.match(text)
        !match.nil? && !match[2].empty? && match[2].match?(/\A[0-9]/) && (match[1] || !match[2].include?(":")) &&
          (match[3].nil? || !match[3].empty?)
      end

      attr_reader :epoch, :upstream, :revision

      def self.parse(text)
        text.is_a?(Version) ? text : new(text)
      end

      def initialize(text)
        @text = text.strip
        match = FORMAT.match(@text)
        raise ArgumentError, "invalid Debian version #{text.inspect}" unless match && Version.valid?(@text)

        @epoch = match[1].to_i
        @upstream = match[2]
        @revision = match[3] || ""
        freeze
      end

      def <=>(other)
        other = Version.parse(other)
        return epoch <=> other.epoch unless epoch == other.epoch

        result = self.class.compare_part(upstream, other.upstream)
        result.zero? ? self.class.compare_part(revision, other.revision) : result
      end

      def eql?(other)
        other.is_a?(Version) && (self <=> other).zero?
      end

      # Equal versions hash alike: dpkg compares runs of digits as numbers
      # ("1.0" is "1.00") and treats a missing trailing digit run as 0 ("1.0"
      # is "1."; an empty revision is "0"), so the key is each part as
      # (non-digit run, number) pairs without trailing ("", 0) pairs.
      def hash
        [epoch, self.class.key(upstream), self.class.key(revision)].hash
      end

      def self.key(part)
        pairs = part.scan(/(\D*)(\d*)/).map { |letters, digits| [letters, digits.to_i] }
        pairs.pop while pairs.last == ["", 0]
        pairs
      end

      def to_s
        @text
      end

      # dpkg's verrevcmp
      def self.compare_part(left, right)
        i = 0
        j = 0
        while i < left.size || j < right.size
          first_diff = 0
          while (i < left.size && !digit?(left[i])) || (j < right.size && !digit?(right[j]))
            ac = order(left[i])
            bc = order(right[j])
            return ac <=> bc if ac != bc

            i += 1
            j += 1
          end
          i += 1 while i < left.size && left[i] == "0"
          j += 1 while j < right.size && right[j] == "0"
          while i < left.size && digit?(left[i]) && j < right.size && digit?(right[j])
            first_diff = left[i].ord - right[j].ord if first_diff.zero?
            i += 1
            j += 1
          end
          return 1 if i < left.size && digit?(left[i])
          return -1 if j < right.size && digit?(right[j])
          return first_diff <=> 0 unless first_diff.zero?
        end
        0
      end

      def self.digit?(char)
        char && char >= "0" && char <= "9"
      end

      # The weight of one non-digit character (nil: the end of the string).
      def self.order(char)
        if char.nil? || digit?(char) then 0
        elsif char.match?(/[A-Za-z]/) then char.ord
        elsif char == "~" then -1
        else char.ord + 256
        end
      end
    end
  end
end
