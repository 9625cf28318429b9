# frozen_string_literal: true

require_relative "../error"

module Relspec
  module Plan
    # One distribution codename and architecture a release is built for.
    Target = Struct.new(:codename, :arch) do
      def self.parse(text)
        codename, arch = text.to_s.split("/", 2)
        raise InvalidOption, "a target is written codename/arch (e.g. bionic/amd64), not #{text.inspect}" \
          unless codename && arch && !codename.empty? && !arch.empty?

        new(codename, arch).freeze
      end

      # The targets a `--target codename/arch` option selects among +targets+
      # (all of them when +text+ is nil); an unknown one is an Error.
      def self.select(text, targets, release)
        return targets if text.nil?

        wanted = parse(text)
        found = targets.find { |target| target == wanted }
        raise Error, "#{text} is not a target of #{release} (#{targets.join(', ')})" unless found

        [found]
      end

      # Every target of an effective spec, sorted.
      def self.all(effective)
        effective.targets.flat_map { |codename, archs| archs.map { |arch| new(codename, arch).freeze } }.sort_by(&:to_s)
      end

      def to_s
        "#{codename}/#{arch}"
      end
    end
  end
end
