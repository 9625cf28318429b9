# frozen_string_literal: true

module Relspec
  module Apt
    # Relationship fields (Depends, Build-Depends, Provides, …) as
    # deb-control(5) writes them: comma-separated groups of `|` alternatives,
    # each `name[:archqual] [(op version)] [[arch …]] [<profile …> …]`.
    module Dependency
      # One alternative. +operator+ is one of << <= = >= >> (nil: any version).
      Relation = Struct.new(:name, :arch_qualifier, :operator, :version, :architectures, :profiles, keyword_init: true) do
        def to_s
          text = arch_qualifier ? "#{name}:#{arch_qualifier}" : name.dup
          text << " (#{operator} #{version})" if operator
          text << " [#{architectures.join(' ')}]" unless architectures.empty?
          profiles.each { |group| text << " <#{group.join(' ')}>" }
          text
        end
      end

      RELATION = /\A
        (?<name>[a-z0-9][a-z0-9.+-]*)(?::(?<qualifier>[a-z0-9-]+))?\s*
        (?:\(\s*(?<operator><<|<=|=|>=|>>|<|>)\s*(?<version>[0-9][^\s)]*)\s*\))?\s*
        (?:\[(?<archs>[^\]]*)\])?\s*
        (?<profiles>(?:<[^>]*>\s*)*)
      \z/x

      # Old spellings dpkg still accepts.
      OPERATORS = { "<" => "<=", ">" => ">=" }.freeze

      module_function

      # Array of groups, each an Array of alternative Relations. Raises
      # ArgumentError naming the part it cannot read.
      def parse(field)
        return [] if field.nil? || field.strip.empty?

        field.split(",").map(&:strip).reject(&:empty?).map do |group|
          group.split("|").map { |alternative| relation(alternative.strip) }
        end
      end

      def relation(text)
        match = RELATION.match(text)
        raise ArgumentError, "cannot read the relation #{text.inspect}" unless match

        operator = match[:operator]
        Relation.new(
          name: match[:name], arch_qualifier: match[:qualifier],
          operator: operator && OPERATORS.fetch(operator, operator), version: match[:version],
          architectures: match[:archs].to_s.split, profiles: match[:profiles].scan(/<([^>]*)>/).map { |(g)| g.split }
        ).freeze
      end

      # Names a Provides field makes available (versions dropped).
      def provided_names(field)
        parse(field).flatten.map(&:name)
      end
    end
  end
end
