# frozen_string_literal: true

require_relative "../error"
require_relative "../frozen"

module Relspec
  module Builder
    # How much the kept build-dependency layers of a run may take
    # (docs/build.md, "A bound on the kept layers"): before a new layer is
    # made, the least recently used layers no build uses are given up until
    # the layers, the new one included (an estimate), fit the budget and
    # leave a floor free on their file system and, on tmpfs, in memory;
    # when even that cannot make room, the build goes without a layer. On
    # tmpfs the layers are memory: kept for the whole run, a real release's
    # 56 layers took 22 GB of a 24 GB machine and compiles were OOM-killed.
    class LayerBudget
      GIB = 1024**3
      # room a build and its neighbours need (UnpackDir::NEEDED's reasoning)
      FLOOR = 6 * GIB
      # at most this on tmpfs, whatever its size
      TMPFS_CAP = 8 * GIB
      # the first layer's estimate; later ones take the last made's size
      ESTIMATE = GIB
      UNITS = { "" => 1, "K" => 1024, "M" => 1024**2, "G" => GIB }.freeze
      VARIABLE = "RELSPEC_LAYER_BUDGET"

      # A kept (or being made) layer: +key+ its set's, +bytes+ its size,
      # +used+ when it was last given to a build (a count: larger is later),
      # +in_use+ a build runs over it or it is being made.
      Layer = Struct.new(:key, :bytes, :used, :in_use, keyword_init: true)
      # +make+: whether to make the new layer; +evict+: keys of the layers
      # to remove first (least recently used first); +reason+: why not.
      Decision = Struct.new(:make, :evict, :reason, keyword_init: true)

      # The budget in bytes for layers on a file system of +size+ bytes
      # (nil when unknown), +tmpfs+ or not: a quarter of it, at most
      # TMPFS_CAP on tmpfs; +override+ (bytes, RELSPEC_LAYER_BUDGET's: .parse) wins.
      def self.bytes(size, tmpfs:, override: nil)
        return override if override

        quarter = size ? size / 4 : TMPFS_CAP
        tmpfs ? [quarter, TMPFS_CAP].min : quarter
      end

      # Bytes of +text+: a number, or one with K, M or G (binary units).
      def self.parse(text)
        match = text.to_s.strip.match(/\A(\d+)\s*([KMG]?)\z/i)
        raise InvalidOption, "#{VARIABLE}=#{text.to_s.inspect}: not a size (bytes, or a number with K, M or G)" unless match

        match[1].to_i * UNITS.fetch(match[2].upcase)
      end

      # A size for a person: "1.5 GB" (binary units, as the budget's).
      def self.human(bytes)
        format("%.1f GB", bytes.to_f / GIB)
      end

      attr_reader :budget, :floor

      def initialize(budget:, floor: FLOOR)
        @budget = budget
        @floor = floor
      end

      # What to do before making a layer of about +estimate+ bytes beside
      # +layers+ (Layer), with +free+ bytes free on their file system and
      # +available+ bytes of memory (nil when not on tmpfs; either nil when
      # unknown: not checked). Never evicts a layer in use; evicts nothing
      # when even evicting all it may leaves no room.
      def decide(layers, estimate:, free:, available:)
        total = layers.sum(&:bytes)
        room = [free, available]
        evict = []
        candidates = layers.reject(&:in_use).sort_by { |layer| [layer.used, layer.key] }
        loop do
          return decision(true, evict, nil) if fits?(total, estimate, free, available)

          layer = candidates.shift
          return decision(false, [], reason(total, estimate, *room)) unless layer

          evict << layer.key
          total -= layer.bytes
          # removing a layer frees its bytes on the file system (and, on tmpfs, in memory)
          free &&= free + layer.bytes
          available &&= available + layer.bytes
        end
      end

      private

      def fits?(total, estimate, free, available)
        total + estimate <= @budget && [free, available].compact.all? { |room| room - estimate >= @floor }
      end

      def decision(make, evict, reason)
        Decision.new(make: make, evict: Frozen.deep(evict), reason: reason&.freeze).freeze
      end

      def reason(total, estimate, free, available)
        said = ["the layers in use take #{LayerBudget.human(total)}, a new one about #{LayerBudget.human(estimate)}, " \
                "of a budget of #{LayerBudget.human(@budget)}"]
        said << "#{LayerBudget.human(free)} free on their file system" if free
        said << "#{LayerBudget.human(available)} of memory available" if available
        "no room (#{said.join('; ')}; #{LayerBudget.human(@floor)} must stay free)"
      end
    end
  end
end
