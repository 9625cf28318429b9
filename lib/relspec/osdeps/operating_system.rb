# frozen_string_literal: true

require_relative "../error"

module Relspec
  module Osdeps
    # The system a user's workspace runs on, as autoproj names it:
    # "ubuntu,debian:18.04,bionic" → names [ubuntu debian], versions [18.04 bionic].
    OperatingSystem = Struct.new(:names, :versions) do
      def self.parse(text)
        names, versions = text.to_s.split(":", 2)
        names = names.to_s.split(",").map(&:strip).reject(&:empty?)
        versions = versions.to_s.split(",").map(&:strip).reject(&:empty?)
        if names.empty? || versions.empty?
          raise InvalidOption, "--os is written names:versions, e.g. ubuntu,debian:18.04,bionic (got #{text.inspect})"
        end

        new(names.freeze, versions.freeze).freeze
      end

      # The Debian name an osdeps entry ({type key => {labels key => name}})
      # gives for this system, or nil.
      def resolve(entry)
        return nil unless entry.is_a?(Hash)

        entry.each do |type_key, by_labels|
          next unless type_key.to_s.split(",").intersect?(names) && by_labels.is_a?(Hash)

          by_labels.each do |labels_key, deb|
            return deb if labels_key.to_s.split(",").intersect?(versions)
          end
        end
        nil
      end
    end
  end
end
