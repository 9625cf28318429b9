# frozen_string_literal: true

require_relative "../architectures"
require_relative "../names"
require_relative "../value_kind"
require_relative "../../diagnostic"
require_relative "../../suggestion"

module Relspec
  module ReleaseSpec
    module Rules
      # `targets`: distribution codename => architectures. Whether a codename
      # is a known distribution depends on inherited `distributions`, so that
      # check lives in the hierarchy rules.
      module Targets
        def self.call(file)
          check(file, ["targets"], file.usable("targets"))
        end

        def self.check(file, path, targets)
          return [] unless targets.is_a?(Hash)

          if targets.empty?
            return [Diagnostic.error("empty-targets", "\"targets\" lists no distribution", location: file.location(path),
                                                                                           hint: "add `bionic: [amd64]` style entries, or remove the key to use the parent's")]
          end

          targets.flat_map { |codename, architectures| check_target(file, path + [codename], codename, architectures) }
        end

        def self.check_target(file, path, codename, architectures)
          unless Names::CODENAME.match?(codename)
            return [Diagnostic.error("unknown-distribution", "invalid distribution codename #{codename.inspect}",
                                     location: file.key_location(path), hint: "codenames are lowercase, e.g. bionic")]
          end
          unless architectures.is_a?(Array)
            return [Diagnostic.error("wrong-type", "the architectures of #{codename} must be a list, " \
                                                   "found #{ValueKind.of(architectures)}",
                                     location: file.location(path), hint: "write #{codename}: [amd64]")]
          end
          if architectures.empty?
            return [Diagnostic.error("empty-targets", "#{codename} lists no architecture", location: file.location(path),
                                                                                           hint: "write #{codename}: [amd64], or remove #{codename}")]
          end

          check_architectures(file, path, codename, architectures)
        end

        def self.check_architectures(file, path, codename, architectures)
          seen = []
          architectures.each_with_index.filter_map do |arch, index|
            location = file.location(path + [index])
            problem =
              if !arch.is_a?(String)
                Diagnostic.error("wrong-type", "an architecture must be a name, found #{ValueKind.of(arch)}", location: location)
              elsif !Architectures.known?(arch)
                hint = Architectures::ALIASES[arch] ? "Debian calls it \"#{Architectures::ALIASES[arch]}\"" : nil
                hint ||= Suggestion.hint(arch, Architectures::KNOWN) || "known: #{Architectures::KNOWN.join(', ')}"
                Diagnostic.error("unknown-architecture", "unknown architecture #{arch.inspect} for #{codename}",
                                 location: location, hint: hint)
              elsif seen.include?(arch)
                Diagnostic.error("duplicate-architecture", "#{arch} is listed twice for #{codename}", location: location,
                                                                                                      hint: "list it once")
              end
            seen << arch
            problem
          end
        end
      end
    end
  end
end
