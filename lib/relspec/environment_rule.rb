# frozen_string_literal: true

module Relspec
  # The one rule of what an installed package's env.yml may change in a
  # workspace: relspec's compile keeps only such entries in the env.yml it
  # writes (Debian::Environment), and the package set's init.rb checks each
  # again before the workspace's environment sees it (Osdeps::Trust). A
  # top-level leaf, plain Ruby without requires: the package set ships it,
  # and debian/ reads it without depending on osdeps/.
  module EnvironmentRule
    # Where releases install (IndexCheck::PREFIX, Osdeps::Trust::PREFIX);
    # every env.yml and every path an env.yml adds is below it.
    PREFIX = "/opt/rock"
    # The variables an installed package's env.yml may change, each value
    # an absolute path below PREFIX: the ones relspec writes (Debian::Environment)
    # and the search paths Rock's package sets add. Anything else
    # (LD_PRELOAD, RUBYOPT, BASH_ENV, …) would run code in every process
    # of the workspace. docs/releasing.md lists them.
    PATH_VARIABLES = %w[CMAKE_PREFIX_PATH GEM_PATH GLEW_DEST LD_LIBRARY_PATH OROGEN_PLUGIN_PATH OSG_FILE_PATH
                        OWLAPI_ONTOLOGIES_PATH PATH PKG_CONFIG_PATH PYTHONPATH QT_PLUGIN_PATH ROCK_BUNDLE_PATH
                        ROCK_PREFIX ROCK_WEBAPP RTT_COMPONENT_PATH RUBYLIB Syskit_DIR TYPELIB_PLUGIN_PATH
                        TYPELIB_RUBY_PLUGIN_PATH VIZKIT_PLUGIN_RUBY_PATH].freeze
    # Settings the real Rock package sets give a package (orocos.toolchain:
    # typelib's importer, RTT's target; rock.core: orocos.rb's name
    # service and test transport, syskit's telemetry switch), each value
    # one plain word: no path to run, no shell syntax.
    WORD_VARIABLES = %w[ORBInitRef OROCOSRB_TEST_USE_MQUEUE OROCOS_TARGET SYSKIT_HAS_GRPC TYPELIB_CXX_LOADER].freeze
    WORD = %r{\A[A-Za-z0-9_.:=/-]{1,200}\z}
    ENVIRONMENT_TYPES = %i[add_path add set].freeze

    module_function

    # One variable of an env.yml: +entry+ {type:, values:, priority:}.
    # +prefix+: where the release installs (the package set's is PREFIX;
    # relspec's compile gives the release's own).
    def problem(name, entry, prefix: PREFIX)
      word = WORD_VARIABLES.include?(name)
      return "#{name.inspect} is not a variable the package set lets a package change" unless word || PATH_VARIABLES.include?(name)
      return "#{name}: is not a mapping of type and values" unless entry.is_a?(Hash)
      return "#{name}: the type #{entry[:type].inspect} is not one of add_path, add, set" unless ENVIRONMENT_TYPES.include?(entry[:type])

      values = entry[:values].is_a?(Array) ? entry[:values] : [entry[:values]]
      return word_values(name, entry, values) if word

      bad = values.find { |value| !below_prefix?(value, prefix) }
      bad.nil? ? nil : "#{name}: #{bad.inspect} is not a path below #{prefix}"
    end

    def word_values(name, entry, values)
      return "#{name}: is set (one word), not added to" unless entry[:type] == :set && values.size == 1
      return nil if values.first.is_a?(String) && WORD.match?(values.first)

      "#{name}: #{values.first.inspect} is not one plain word"
    end

    def below_prefix?(value, prefix = PREFIX)
      value.is_a?(String) && value.start_with?("#{prefix}/") && !value.match?(/[[:cntrl:]:]/) &&
        File.expand_path(value) == value.chomp("/")
    end
  end
end
