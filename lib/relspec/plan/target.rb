# frozen_string_literal: true

module Relspec
  module Plan
    # One distribution codename and architecture a release is built for.
    Target = Struct.new(:codename, :arch) do
      def self.parse(text)
        codename, arch = text.to_s.split("/", 2)
        raise ArgumentError, "a target is written codename/arch (e.g. bionic/amd64), not #{text.inspect}" \
          unless codename && arch && !codename.empty? && !arch.empty?

        new(codename, arch).freeze
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
