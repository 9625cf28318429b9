# frozen_string_literal: true

module Relspec
  module Publish
    # The automatic debug-symbol packages dh_strip makes of compiled code
    # (<package>-dbgsym_<version>_<arch>.deb, .ddeb on Ubuntu). The build
    # keeps and records them because the ABI dumps are made from them
    # (Builder::AbiDumper); the release's repository carries them only when its
    # spec asks (`repository: { debug_symbols: true }`): they are often
    # larger than the packages themselves and no robot installs them.
    module DebugSymbols
      # dpkg's file name: name, version, architecture, each without "_".
      PACKAGE = /-dbgsym_[^_]+_[^_]+\.d?deb\z/

      module_function

      # Whether the file at +path+ is a debug-symbol package.
      def package?(path)
        PACKAGE.match?(File.basename(path))
      end

      # The .debs of +paths+ that the repository receives: all of them when
      # +included+, else those that are not debug-symbol packages. A .ddeb
      # is never among them (Upload keeps only .deb files).
      def select(paths, included:)
        included ? paths : paths.reject { |path| package?(path) }
      end
    end
  end
end
