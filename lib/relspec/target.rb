# frozen_string_literal: true

require_relative "error"

module Relspec
  # One distribution codename and architecture a release is built for: the
  # one target value of plan, why, check, compile, build and publish.
  Target = Struct.new(:codename, :arch) do
    def self.parse(text)
      codename, arch = text.to_s.split("/", 2)
      raise InvalidOption, "a target is written codename/arch (e.g. bionic/amd64), not #{text.inspect}" \
        unless codename && arch && !codename.empty? && !arch.empty?

      new(codename, arch).freeze
    end

    # The one `--target codename/arch` selection: the targets +wanted+ (nil:
    # all of +targets+; a String or several) names among +targets+, in the
    # order asked; an unknown one is an InvalidOption.
    def self.select(wanted, targets, release)
      names = Array(wanted).uniq
      return targets if names.empty?

      names.map do |text|
        parsed = parse(text)
        targets.find { |target| target == parsed } or
          raise InvalidOption, "#{text} is not a target of #{release} (#{targets.join(', ')})"
      end
    end

    # Every target of an effective spec, sorted.
    def self.all(effective)
      effective.targets.flat_map { |codename, archs| Array(archs).map { |arch| new(codename, arch).freeze } }.sort_by(&:to_s)
    end

    def to_s
      "#{codename}/#{arch}"
    end

    # The folder name of the target in the output tree and in caches.
    def dir_name
      "#{codename}-#{arch}"
    end
  end
end
