# frozen_string_literal: true

module Relspec
  # The one spelling of Debian's package name rule (policy 5.6.1 Source,
  # 5.6.7 Package): lowercase letters, digits, + - . ; at least two
  # characters, starting with a letter or digit. Nothing apt or a shell
  # could read as an option or syntax (a leading -, spaces, =, quotes).
  # Plain Ruby without requires: the package set ships it (Osdeps::Trust).
  module DebianName
    PATTERN = /\A[a-z0-9][a-z0-9+.-]+\z/
    # The leading part of names (a spec's package_prefix): the same
    # characters, and one is enough since the name goes on after it.
    PREFIX = /\A[a-z0-9][a-z0-9+.-]*\z/

    module_function

    def valid?(name)
      name.is_a?(String) && PATTERN.match?(name)
    end

    # nil when +name+ is one, else why not.
    def problem(name)
      return nil if valid?(name)

      "#{name.inspect} is not a Debian package name (lowercase letters, digits, + - ., not starting with - or .)"
    end
  end
end
