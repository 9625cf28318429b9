# frozen_string_literal: true

require "thor"
require_relative "strict_commands"
require_relative "checked_options"
require_relative "../osdeps"

module Relspec
  module CLI
    # `relspec osdeps …`: the files that let autoproj workspaces use a
    # release's binaries (rock-osdeps package set format). Each command is
    # one call of the use case (lib/relspec/osdeps.rb) and prints its result.
    class OsdepsCommands < Thor
      include CheckedOptions
      include StrictCommands

      namespace "osdeps"

      def self.exit_on_failure?
        true
      end

      desc "render SPEC", "Write releases/<release>/osdeps/<release>-<arch>.yml (also: relspec osdeps SPEC)"
      long_desc <<~TEXT
        Maps every package the release provides (built here or inherited, under the
        Debian name of the release that holds it) to its Debian package, per
        distribution, one file per architecture. By default from the plan (what the
        release will hold); with --from-repository, only what the release's repository
        (and its ancestors') really hold, listing planned packages that are missing.
      TEXT
      option :from_repository, type: :boolean, default: false, desc: "Only packages the repositories hold"
      option :timeout, type: :numeric, default: 10, desc: "HTTP timeout in seconds"
      def render(path)
        written = Osdeps.render(path, timeout: options[:timeout], from_repository: options[:from_repository])
        written.written.each { |target, changed| $stderr.puts("#{changed ? 'wrote' : 'unchanged'} #{target}") }
        written.missing.each { |line| $stderr.puts("missing from the repository: #{line}") }
      end

      desc "index", "Write releases/releases.yml, the release index of the rock-osdeps package set"
      option :specs, type: :string, default: "specs", desc: "The folder of release specs"
      option :repo_url, type: :string, desc: "Base URL of the releases (default: the one most releases share)"
      option :public_key, type: :string, desc: "URL of the key that signs the releases"
      def index
        written = Osdeps.index(specs: options[:specs], repo_url: options[:repo_url], public_key: options[:public_key])
        $stderr.puts("#{written.changed ? 'wrote' : 'unchanged'} #{written.path}")
      end

      desc "package-set", "Write relspec's autoproj package set for the releases of specs/ (default: build/package-set)"
      long_desc <<~TEXT
        A ready autoproj package set (source.yml, init.rb, data/) for every release of
        --specs, from their published repositories: users add it to their manifest,
        choose a release in autoproj/relspec.yml, and autoproj installs the release's
        binaries with apt instead of building those packages (docs/releasing.md).
        Only relspec's files in --out change, each only when its bytes do: .git and
        other files beside lib/ and data/ stay (a git checkout keeps its history).
      TEXT
      option :specs, type: :string, default: "specs", desc: "The folder of release specs"
      option :out, type: :string, default: "build/package-set", desc: "The package set's folder"
      def package_set
        written = Osdeps.package_set(specs: options[:specs], out: options[:out])
        result = written.result
        summary = "#{result.written.size} of #{written.files} files written, #{result.removed.size} removed"
        $stderr.puts(result.changed? ? "wrote #{written.out} (#{summary})" : "unchanged #{written.out} (#{written.files} files)")
      end
      map "package-set" => :package_set

      desc "select", "Apply a user's deb_blacklist.yml: write rock-osdeps.osdeps and rock-osdeps.inactive"
      long_desc <<~TEXT
        Reads the osdeps files of --release and its ancestors (releases.yml's
        depends_on) from --data, keeps the Debian package of each autoproj package for
        --os, removes every package the blacklist names (names, globs, /regex/) and
        every package that depends on one (computed from the Depends of the given
        Packages indices), and writes rock-osdeps.osdeps ({package: {default: name}})
        and rock-osdeps.inactive (what was disabled and why) into --output.
      TEXT
      option :release, type: :string, required: true, desc: "The release the workspace uses"
      option :arch, type: :string, required: true, desc: "The workspace's architecture"
      option :os, type: :string, required: true, desc: "autoproj's names:versions of the system, e.g. ubuntu,debian:18.04,bionic"
      option :data, type: :string, default: "releases", desc: "Folder with releases.yml and the osdeps files"
      option :blacklist, type: :string, desc: "A deb_blacklist.yml"
      option :index, type: :array, default: [], desc: "Packages files or repository URLs for reverse dependencies"
      option :trusted, type: :boolean, default: false, desc: "Read repository URLs without checking signatures"
      option :keyring, type: :string, desc: "Keyring verifying repository URLs"
      option :timeout, type: :numeric, default: 10, desc: "HTTP timeout in seconds (repository URLs)"
      option :output, type: :string, default: ".", desc: "Where to write rock-osdeps.osdeps and rock-osdeps.inactive"
      def select
        require_relative "select_command"
        SelectCommand.new(options, err: $stderr).call
      end
    end
  end
end
