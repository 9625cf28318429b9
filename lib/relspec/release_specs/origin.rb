# frozen_string_literal: true

module Relspec
  module ReleaseSpec
    # Where an effective value was written: a spec file and the key path in
    # it, or nowhere (a built-in default).
    class Origin
      attr_reader :file, :path

      def self.default
        DEFAULT
      end

      def initialize(file, path)
        @file = file
        @path = path.freeze
        freeze
      end

      def default?
        file.nil?
      end

      def location
        default? ? nil : file.key_location(path)
      end

      def to_s
        default? ? "default" : location.to_s
      end

      DEFAULT = new(nil, [])
    end
  end
end
