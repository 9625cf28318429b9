# frozen_string_literal: true

module Relspec
  module Plan
    # Package names in dependency order: in waves, each wave the packages
    # whose dependencies are all in earlier waves, by name. A dependency
    # cycle (autoproj refuses them, snapshots might not) does not stop the
    # order: the first remaining name goes next.
    module BuildOrder
      module_function

      # +names+: the packages to order; dependencies outside +names+ are ignored.
      def of(catalog, names)
        wanted = names.to_h { |name| [name, true] }
        waiting = {}
        dependents = Hash.new { |hash, name| hash[name] = [] }
        names.each do |name|
          deps = catalog.package(name).build_dependencies.select { |dep| wanted[dep] && dep != name }.uniq
          waiting[name] = deps.size
          deps.each { |dep| dependents[dep] << name }
        end
        ordered = []
        wave = waiting.select { |_, count| count.zero? }.keys.sort
        until ordered.size == names.size
          wave = [waiting.keys.min] if wave.empty?
          following = []
          wave.each do |name|
            waiting.delete(name)
            ordered << name
            dependents.fetch(name, []).each do |dependent|
              next unless waiting.key?(dependent)

              following << dependent if (waiting[dependent] -= 1).zero?
            end
          end
          wave = following.sort
        end
        ordered
      end
    end
  end
end
