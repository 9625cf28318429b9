# frozen_string_literal: true

require "stringio"
require "autobuild"

module Relspec
  class Catalog
    # What autoproj says while relspec loads a workspace (warnings about the
    # package sets, such as an osdeps entry a package set overrides),
    # collected instead of printed as it comes: relspec loads the workspace
    # once per target distribution, and autoproj would repeat every message
    # for each. Each message is given once, in the order first said, as
    # plain text (autoproj styles it for a terminal), when the load ends,
    # also when it fails (the messages may say why).
    class AutoprojMessages
      # autoproj's display, with every message (whatever stream autoproj
      # asks for: warnings name STDERR) handed to +messages+.
      class Display < Autobuild::ProgressDisplay
        def initialize(messages)
          super(StringIO.new)
          @messages = messages
          self.progress_enabled = false
        end

        def message(message, *_style, io: nil, force: false)
          @messages.add(message.to_s) unless silent? && !force
        end
      end

      def initialize
        @messages = []
      end

      # One line as autoproj gives it. A warning of several lines comes as
      # several calls, the later ones indented after "WARN:": they belong to
      # the message before.
      def add(line)
        if continuation?(line) && !@messages.empty?
          @messages.last << line
        else
          @messages << [line]
        end
      end

      # Every message once, in order, a line each.
      def to_s
        @messages.uniq.flatten.map { |line| "#{line.rstrip}\n" }.join
      end

      private

      def continuation?(line)
        line.match?(/\A\s*(WARN|ERROR):  /)
      end
    end
  end
end
