# frozen_string_literal: true

module Relspec
  module Plan
    # Package names in dependency order: dependencies first, then by name.
    # A dependency cycle (autoproj refuses them, snapshots might not) does not
    # stop the order: the first remaining name goes next.
    module BuildOrder
      module_function

      # +names+: the packages to order; dependencies outside +names+ are ignored.
      def of(catalog, names)
        wanted = names.to_h { |name| [name, true] }
        pending = names.sort
        done = {}
        ordered = []
        until pending.empty?
          ready = pending.select do |name|
            catalog.package(name).build_dependencies.all? { |dep| done[dep] || !wanted[dep] }
          end
          ready = [pending.first] if ready.empty?
          ready.each do |name|
            ordered << name
            done[name] = true
          end
          pending -= ready
        end
        ordered
      end
    end
  end
end
