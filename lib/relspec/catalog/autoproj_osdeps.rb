# frozen_string_literal: true

module Relspec
  class Catalog
    # How autoproj's OS package resolver sees the osdeps of one load (part
    # of AutoprojLoader, required with autoproj): each name classified for
    # the catalog, and the keys autoproj silently matches with no system.
    module AutoprojOsdeps
      module_function

      # {"apt" => […], "gems" => […], …} for one osdep name.
      def classify(resolver, name)
        result = Hash.new { |hash, key| hash[key] = [] }
        case resolver.availability_of(name)
        when Autoproj::OSPackageResolver::NONEXISTENT then result["nonexistent"] << name
        when Autoproj::OSPackageResolver::IGNORE then result["ignored"] << name
        when Autoproj::OSPackageResolver::AVAILABLE then add_resolved(resolver, name, result)
        # defined, but not for this system: autoproj excludes it (and what needs it) here
        when Autoproj::OSPackageResolver::WRONG_OS, Autoproj::OSPackageResolver::UNKNOWN_OS then result["other_os"] << name
        else result["unresolved"] << name
        end
        result
      end

      def add_resolved(resolver, name, result)
        resolver.resolve_package(name).each do |handler, status, names|
          next unless status == Autoproj::OSPackageResolver::FOUND_PACKAGES

          case handler
          when resolver.os_package_manager then result["apt"].concat(names)
          when "gem" then result["gems"].concat(names)
          else result["unresolved"] << name
          end
        end
      end

      # autoproj splits an osdeps key at "," and compares the parts as they
      # are: "ubuntu, debian" names " debian", which matches no system, so
      # the entry silently applies nowhere. Said once, naming key and file.
      def warn_spaced_keys(resolver)
        resolver.all_definitions.each do |name, entries|
          entries.each do |file, definition|
            spaced_keys(definition).each do |key|
              Autoproj.warn("osdeps key #{key.inspect} of #{name} in #{Array(file).join(', ')}: autoproj splits keys at commas without " \
                            "removing spaces, so it matches no system; write #{key.split(',').map(&:strip).join(',').inspect}")
            end
          end
        end
      end

      def spaced_keys(definition)
        return [] unless definition.is_a?(Hash)

        definition.flat_map do |key, value|
          own = key.is_a?(String) && key.split(",").any? { |part| part != part.strip } ? [key] : []
          own + spaced_keys(value)
        end
      end
    end
  end
end
