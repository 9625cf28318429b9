# frozen_string_literal: true

require_relative "../debian_name"
require_relative "../release_specs/names"

module Relspec
  module Osdeps
    # What the package set accepts from a repository before it reaches apt
    # (run as root), /etc/apt or a workspace's environment. relspec checks it
    # when it writes a package set, and the package set's init.rb checks it
    # again when it reads one (the folder is a git checkout anybody with
    # push access can change). Plain Ruby, requiring only files the package
    # set ships: init.rb loads it in users' workspaces, where relspec is not
    # installed.
    #
    # Each check returns nil when the value is fine, else why it is not
    # (text for a message that names the file and the entry).
    module Trust
      # Release names: they become file names.
      RELEASE_NAME = ReleaseSpec::Names::RELEASE
      # A plain http(s) URL: host, optional port, path segments; nothing that
      # ends an apt line or adds an option to it (spaces, newlines, [ ]).
      URL = %r{\Ahttps?://[A-Za-z0-9.-]+(:[0-9]{1,5})?(/[A-Za-z0-9._~%+-]+)*/?\z}
      # The keyring of a release inside the package set's data/.
      KEY = %r{\Akeys/[a-z][a-z0-9.+-]*\.gpg\z}
      # Where releases install (IndexCheck::PREFIX); every env.yml and
      # every path an env.yml adds is below it.
      PREFIX = "/opt/rock"
      # The variables an installed package's env.yml may change, each value
      # an absolute path below PREFIX: the ones relspec writes (Debian::DebianDir)
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

      # Debian names (DebianName): they reach `apt-get install` as root.
      def debian_name(name)
        DebianName.problem(name)
      end

      def release_name(name)
        return nil if name.is_a?(String) && RELEASE_NAME.match?(name)

        "#{name.inspect} is not a release name"
      end

      def url(url)
        return nil if url.is_a?(String) && URL.match?(url)

        "the URL #{url.inspect} is not a plain http(s) URL"
      end

      # +entry+: a release's entry of data/apt.yml ({"url", "trusted", "key"}).
      def apt_entry(entry)
        return "is not a mapping of url, trusted and key" unless entry.is_a?(Hash)

        url(entry["url"]) || key(entry)
      end

      def key(entry)
        key = entry["key"]
        if key.nil?
          return nil if entry["trusted"] == true

          return "has no key and does not say trusted: true: apt would read it unverified"
        end
        return "is trusted: true and has a key: one or the other" if entry["trusted"] == true
        return nil if key.is_a?(String) && KEY.match?(key)

        "the key #{key.inspect} is not a keys/<release>.gpg of the package set"
      end

      # +path+ of an env.yml: a regular file whose real path is below PREFIX.
      def environment_file(path)
        real = File.realpath(path)
        return nil if real.start_with?("#{PREFIX}/") && File.file?(real)

        "is #{real}, outside #{PREFIX}"
      end

      # One variable of an env.yml: +entry+ {type:, values:, priority:}.
      # +prefix+: where the release installs (the package set's is PREFIX;
      # relspec's compile gives the release's own).
      def environment(name, entry, prefix: PREFIX)
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
end
