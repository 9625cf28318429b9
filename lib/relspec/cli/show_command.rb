# frozen_string_literal: true

require "json"
require_relative "../release_specs"
require_relative "annotated_yaml"

module Relspec
  module CLI
    # `relspec show SPEC`: the effective spec after inheritance, optionally
    # with the file and line each value comes from.
    class ShowCommand
      def initialize(path:, format:, origins:, out:, err:)
        @path = path
        @format = format
        @origins = origins
        @out = out
        @err = err
      end

      def call
        resolution = ReleaseSpec.resolve(@path)
        @err.puts(resolution.warnings.map(&:to_s)) unless resolution.warnings.empty?
        effective = resolution.effective
        @out.write(@format == "json" ? json(effective) : AnnotatedYaml.render(effective, origins: @origins))
        0
      end

      private

      def json(effective)
        document = { "spec" => effective.to_h }
        document["origins"] = origin_table(effective) if @origins
        "#{JSON.pretty_generate(document)}\n"
      end

      def origin_table(effective)
        table = {}
        effective.to_h.each_key do |key|
          if key == "pins"
            effective.to_h["pins"].each_key { |package| table["pins.#{package}"] = effective.pin_origin(package).to_s }
          elsif effective.origin(key)
            table[key] = effective.origin(key).to_s
          end
        end
        table
      end
    end
  end
end
