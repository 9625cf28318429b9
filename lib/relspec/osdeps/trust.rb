# frozen_string_literal: true

require_relative "../debian_name"
require_relative "../environment_rule"
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
      # every path an env.yml adds is below it (EnvironmentRule).
      PREFIX = EnvironmentRule::PREFIX

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

      # One variable of an env.yml (EnvironmentRule, which relspec's compile
      # applies too).
      def environment(name, entry, prefix: PREFIX)
        EnvironmentRule.problem(name, entry, prefix: prefix)
      end
    end
  end
end
