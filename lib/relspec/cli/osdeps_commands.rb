# frozen_string_literal: true

require "thor"
require_relative "checked_options"
require "fileutils"
require_relative "../atomic_file"
require_relative "../error"

module Relspec
  module CLI
    # `relspec osdeps …`: the files that let autoproj workspaces use a
    # release's binaries (rock-osdeps package set format).
    class OsdepsCommands < Thor
      include CheckedOptions

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
        require_relative "../plan"
        require_relative "../osdeps/renderer"
        result = Plan.compute(path, timeout: options[:timeout])
        effective = result.effective
        present, missing = presence(result)
        files = Osdeps::Renderer.render(result.plan, effective.distributions, present: present)
        dir = File.join(File.dirname(result.lock_path), "osdeps")
        FileUtils.mkdir_p(dir)
        files.each do |arch, text|
          target = File.join(dir, Osdeps::Renderer.file_name(effective.release, arch))
          changed = AtomicFile.update(target, text)
          $stderr.puts("#{changed ? 'wrote' : 'unchanged'} #{target}")
        end
        missing.each { |line| $stderr.puts("missing from the repository: #{line}") }
      end

      desc "index", "Write releases/releases.yml, the release index of the rock-osdeps package set"
      option :specs, type: :string, default: "specs", desc: "The folder of release specs"
      option :repo_url, type: :string, desc: "Base URL of the releases (default: the one most releases share)"
      option :public_key, type: :string, desc: "URL of the key that signs the releases"
      def index
        require_relative "../release_spec"
        require_relative "../osdeps/release_index"
        library = ReleaseSpec::Library.new(options[:specs])
        raise Error, "#{options[:specs]}/ holds no release spec" if library.names.empty?

        releases = library.paths.map { |path| ReleaseSpec.resolve(path).effective }
        text = Osdeps::ReleaseIndex.render(releases, repo_url: options[:repo_url], public_key: options[:public_key])
        target = File.join(File.dirname(options[:specs]), "releases", "releases.yml").delete_prefix("./")
        FileUtils.mkdir_p(File.dirname(target))
        $stderr.puts("#{AtomicFile.update(target, text) ? 'wrote' : 'unchanged'} #{target}")
      end

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
      option :output, type: :string, default: ".", desc: "Where to write rock-osdeps.osdeps and rock-osdeps.inactive"
      def select
        require_relative "select_command"
        SelectCommand.new(options, err: $stderr).call
      end

      private

      # With --from-repository, a filter keeping what the repositories hold,
      # and the planned packages that are missing.
      def presence(_result)
        return [->(_target, _decision) { true }, []] unless options[:from_repository]

        require_relative "../osdeps/repository_presence"
        presence = Osdeps::RepositoryPresence.new
        [presence.to_proc, presence.missing]
      end
    end
  end
end
