# frozen_string_literal: true

require_relative "../names"
require_relative "../../diagnostic"

module Relspec
  module ReleaseSpec
    module Rules
      # A pin fixes the source of one package to exactly one commit, tag or branch.
      module Pins
        REFS = %w[commit tag branch].freeze

        def self.call(file)
          pins = file.usable("pins")
          return [] unless pins.is_a?(Hash)

          pins.flat_map { |package, pin| check_pin(file, package, pin) }
        end

        def self.check_pin(file, package, pin)
          path = ["pins", package]
          problems = []
          unless Names.package?(package)
            problems << Diagnostic.error("package-name", "#{package.inspect} is not a package name",
                                         location: file.key_location(path),
                                         hint: "autoproj names look like base/types or tools/orocos.rb")
          end
          return problems unless pin.is_a?(Hash)

          problems.concat(check_refs(file, path, package, pin))
        end

        def self.check_refs(file, path, package, pin)
          refs = REFS.select { |ref| pin.key?(ref) }
          if refs.size > 1
            return [Diagnostic.error("pin-ref", "the pin of #{package} sets both #{refs.join(' and ')}",
                                     location: file.key_location(path + [refs[1]]),
                                     hint: "a pin names exactly one of commit, tag or branch")]
          end
          if refs.empty?
            if pin.keys.all? { |key| REFS.include?(key) }
              return [Diagnostic.error("pin-ref", "the pin of #{package} sets none of commit, tag or branch",
                                       location: file.location(path), hint: "write { commit: <sha> } or { tag: <name> }")]
            end

            return []
          end
          commit = pin["commit"]
          return [] if commit.nil? || !commit.is_a?(String) || Names::COMMIT.match?(commit)

          [Diagnostic.error("pin-commit", "commit #{commit.inspect} of #{package} is not a git commit id",
                            location: file.location(path + ["commit"]),
                            hint: "use 7 to 40 lowercase hexadecimal digits; for a tag or branch write tag: or branch:")]
        end
      end
    end
  end
end
