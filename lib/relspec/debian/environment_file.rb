# frozen_string_literal: true

require "json"

module Relspec
  module Debian
    # The env.yml installed in a package's prefix, in the format autoproj
    # package sets read (the rock-osdeps package set loads
    # /opt/rock/*/<deb>/env.yml of every active package with YAML.load_file
    # and hands each variable to the workspace's environment):
    #
    #   VAR:
    #     :type: :add_path        # add_path | add | set | add_prefix
    #     :values: [...]
    #     :priority: 0            # < 0: applied after the others
    #
    # The keys and the type are Ruby symbols because that is what the package
    # set looks up; Yaml::Writer writes plain data only, so the few lines are
    # written here. Values are JSON strings (valid YAML, never read as
    # anything but a string).
    module EnvironmentFile
      TYPES = %i[add_path add set add_prefix].freeze

      module_function

      # +variables+: {name => [values]}, in search order, each added as a
      # path (prepended). +more+: [[type, name, values]] of the package
      # set's own settings; one of a name +variables+ has adds its values
      # in front of them (set: replaces them), as the later operation does
      # in autoproj.
      def render(variables, type: :add_path, priority: 0, more: [])
        raise ArgumentError, "unknown environment type #{type}" unless TYPES.include?(type)

        entries = variables.to_h { |name, values| [name, [type, values]] }
        more.each do |op_type, name, values|
          current = entries[name]
          entries[name] = if op_type == "set" || current.nil? then [op_type.to_sym, values]
                          else [current[0], values + current[1]]
                          end
        end
        out = +"---\n"
        entries.each do |name, (entry_type, values)|
          next if values.empty?

          out << "#{name}:\n  :type: :#{entry_type}\n  :values:\n"
          # package sets prepend one value after the other, so the value to
          # be searched first is written last
          values.reverse_each { |value| out << "  - #{JSON.generate(value)}\n" }
          out << "  :priority: #{Integer(priority)}\n"
        end
        out
      end
    end
  end
end
