# frozen_string_literal: true

require_relative "../apt/version"

module Relspec
  module Mirror
    # What a set of packages needs to be installed from a mirror alone: the
    # packages themselves and, transitively, every package that can satisfy
    # one of their Pre-Depends or Depends. Every alternative of `a | b` and
    # every provider of a virtual package is followed (apt may pick any of
    # them on the machine that installs from the mirror, and aptly's default
    # of the first alternative only is how field mirrors lose packages).
    # A relationship nothing in the index satisfies is kept as Missing with
    # the package that needs it.
    class Closure
      Missing = Struct.new(:relation, :needed_by, keyword_init: true) do
        def to_s
          "#{relation} (needed by #{needed_by})"
        end
      end

      attr_reader :binaries, :missing, :needed_by

      # +index+: BinaryIndex; +seeds+: names that must be in the mirror.
      # Unknown seeds are Missing, needed by "the release".
      def self.of(index, seeds, seed_reason: "the release")
        new(index).tap { |closure| closure.add(seeds, seed_reason) }
      end

      def initialize(index)
        @index = index
        @binaries = {}
        @missing = []
        @needed_by = {} # name => the first package that pulled it in
      end

      def add(seeds, reason)
        queue = []
        seeds.each do |name|
          binary = @index[name]
          next @missing << Missing.new(relation: name, needed_by: reason) unless binary

          queue << take(binary, reason)
        end
        walk(queue.compact)
        self
      end

      def names
        @binaries.keys.sort
      end

      private

      def take(binary, reason)
        return nil if @binaries.key?(binary.name)

        @binaries[binary.name] = binary
        @needed_by[binary.name] = reason
        binary
      end

      def walk(queue)
        until queue.empty?
          binary = queue.shift
          binary.depends.each do |group|
            candidates = group.flat_map { |relation| satisfying(relation) }
            if candidates.empty?
              @missing << Missing.new(relation: group.join(" | "), needed_by: binary.to_s)
              next
            end
            candidates.each { |candidate| (found = take(candidate, binary.to_s)) && (queue << found) }
          end
        end
      end

      # The real package of that name in a fitting version, and the
      # packages providing it (a versioned relation only by a versioned
      # Provides, as dpkg rules).
      def satisfying(relation)
        real = @index[relation.name]
        found = real && fits?(real.version, relation) ? [real] : []
        @index.providers(relation.name).each do |provider, provided|
          next if relation.operator && !(provided.operator == "=" && fits?(provided.version, relation))

          found << provider
        end
        found.uniq
      end

      def fits?(version, relation)
        return true unless relation.operator

        order = Apt::Version.parse(version) <=> Apt::Version.parse(relation.version)
        case relation.operator
        when "=" then order.zero?
        when ">=" then order >= 0
        when "<=" then order <= 0
        when ">>" then order.positive?
        when "<<" then order.negative?
        end
      end
    end
  end
end
