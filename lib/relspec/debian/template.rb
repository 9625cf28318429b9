# frozen_string_literal: true

require "erb"

module Relspec
  module Debian
    # The ERB templates of debian/ (templates/), each compiled once into a
    # method of the Struct its presenter fills: evaluating ERB source on
    # every render (result_with_hash) cost a no-op compile of 400 packages
    # 0.4 s.
    module Template
      DIR = File.join(__dir__, "templates")

      module_function

      # Defines a method of +context+ (a Struct class) per template in
      # +names+; returns {name => method name}.
      def compile(context, names)
        names.to_h do |name|
          method = "render_#{name.delete_suffix('.erb').tr('.', '_')}"
          ERB.new(File.read(File.join(DIR, name)), trim_mode: "-").def_method(context, "#{method}()", name)
          [name, method.to_sym]
        end.freeze
      end

      # The text of template +name+ with +variables+ (a Hash of +context+'s
      # members).
      def render(context, methods, name, variables)
        context.new(**variables).public_send(methods.fetch(name))
      end
    end
  end
end
