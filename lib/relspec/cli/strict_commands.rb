# frozen_string_literal: true

require_relative "../error"
require_relative "../suggestion"

module Relspec
  module CLI
    # Included by every Thor command group (relspec, osdeps, catalog): an
    # unknown option, an unknown subcommand or a wrong number of arguments is
    # one InvalidOption with a "did you mean" hint, never taken as an
    # argument of some other command, and never Thor's own "ERROR:" text.
    module StrictCommands
      def self.included(base)
        base.check_unknown_options!
        base.extend(ClassMethods)
      end

      # Thor's errors, as relspec's. Thor only raises them out of +start+
      # when its config says debug (otherwise it prints and exits itself).
      def self.translated
        yield
      rescue Thor::UnknownArgumentError => e
        unknown = e.unknown.first
        hint = Suggestion.hint(unknown, e.switches)
        raise InvalidOption, "unknown option #{e.unknown.join(', ')}#{"; #{hint}" if hint}"
      rescue Thor::Error => e
        raise InvalidOption, e.message.sub(/\AERROR: /, "").gsub(/\n\s*/, "; ")
      end

      # Class methods Thor calls when a command line does not fit.
      module ClassMethods
        def handle_no_command_error(command, _has_namespace = nil)
          names = all_commands.keys.map { |name| name.tr("_", "-") }.sort
          command = command.tr("_", "-") # Thor turned the user's dashes into underscores
          hint = Suggestion.hint(command, names)
          raise InvalidOption, "#{command_group} has no command #{command.inspect} (commands: #{names.join(', ')})" \
                               "#{"; #{hint}" if hint}"
        end

        def handle_argument_error(command, _error, args, _arity)
          got = args.empty? ? "no arguments" : "the arguments #{args.join(' ')}"
          raise InvalidOption, "usage: #{banner(command)}; got #{got}"
        end

        def command_group
          "relspec #{namespace}"
        end
      end
    end
  end
end
