# frozen_string_literal: true

module Relspec
  class Catalog
    # The command line autoproj gives the oroGen generator for one package
    # (Autobuild::Orogen#regen), read after the package sets ran: --corba,
    # extended states, the type export policy and the transports, then the
    # package sets' raw options (Autobuild::Orogen.orogen_options, then the
    # package's own: rock.core adds --no-rtt-scripting when USE_OCL is off,
    # --import=std, --extensions=metadata_support). What depends on the
    # machine that builds (--parallel-build, --parallel-codegen, the job
    # server) is left to the build. The last word is the .orogen file.
    module OrogenArguments
      # Autobuild::Orogen's class-level settings as the gem sets them; a
      # package set changes them in place, so each load starts from these.
      DEFAULTS = { orogen_options: [], default_type_export_policy: :used, transports: %w[corba typelib mqueue],
                   corba: nil, extended_states: nil }.freeze

      module_function

      def reset
        orogen = Autobuild::Orogen
        orogen.orogen_options.replace(DEFAULTS[:orogen_options])
        orogen.transports.replace(DEFAULTS[:transports])
        orogen.default_type_export_policy = DEFAULTS[:default_type_export_policy]
        orogen.corba = DEFAULTS[:corba]
        orogen.extended_states = DEFAULTS[:extended_states]
      end

      # +autobuild+: the package after loading; nil unless it is an oroGen one.
      def of(autobuild)
        return nil unless autobuild.is_a?(Autobuild::Orogen)

        words = generated(autobuild)
        (Autobuild::Orogen.orogen_options + autobuild.orogen_options).each { |word| add_raw(word, words) }
        words.sort + [orogen_file(autobuild)].compact
      end

      def generated(autobuild)
        words = []
        words << "--corba" if autobuild.corba
        extended = autobuild.extended_states
        words << (extended ? "--extended-states" : "--no-extended-states") unless extended.nil?
        words << "--type-export-policy=#{Autobuild::Orogen.default_type_export_policy}"
        words << "--transports=#{Autobuild::Orogen.transports.sort.uniq.join(',')}"
        words
      end

      # A bare flag replaces what it names (and --no-x replaces --x), as
      # autobuild's add_cmd_to_cmdline does; a word with a value is added.
      def add_raw(word, words)
        flag = word[/\A([\w-]+)\z/, 1]
        return words << word unless flag

        negated = flag.delete_prefix("--no-") if flag.start_with?("--no-")
        words.reject! { |existing| existing.start_with?(flag) || (negated && existing.start_with?("--#{negated}")) }
        words << word
      end

      # The file autobuild would give, when the checkout is there to look in.
      def orogen_file(autobuild)
        autobuild.orogen_file
      rescue ArgumentError
        nil
      end
    end
  end
end
