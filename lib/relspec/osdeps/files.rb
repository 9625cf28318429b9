# frozen_string_literal: true

require "fileutils"
require_relative "renderer"
require_relative "repository_presence"
require_relative "../yaml/writer"
require_relative "../atomic_file"

module Relspec
  module Osdeps
    # The one writer of osdeps files: a release's <release>-<arch>.yml (into
    # releases/<r>/osdeps/ or a repository's osdeps/), the package set's
    # releases.yml and the user side's rock-osdeps.osdeps/.inactive. Each
    # file is replaced by rename; the committed ones only when their content
    # changes, so that git and `make` see no change when there is none.
    module Files
      # +written+: [[path, changed]] in architecture order; +missing+: the
      # planned builds left out because the repository does not hold them.
      Written = Struct.new(:written, :missing, keyword_init: true) do
        def changed_count
          written.count { |_, changed| changed }
        end
      end

      module_function

      # The osdeps files of +decisions+ (Target => {package => Plan::Decision},
      # a ReleasePlan's targets) into +dir+. +effective+: the release's
      # EffectiveSpec. +held_only+: leave out the planned builds, which no
      # repository holds yet (`osdeps --from-repository`; publish gives only
      # what it found held, Publish::HeldPackages).
      def write_release(decisions, effective, dir, held_only: false)
        presence = RepositoryPresence.new if held_only
        files = Renderer.render(decisions, effective.distributions, **(presence ? { present: presence.to_proc } : {}))
        FileUtils.mkdir_p(dir)
        written = files.map do |arch, text|
          path = File.join(dir, Renderer.file_name(effective.release, arch))
          [path, AtomicFile.update(path, text)]
        end
        Written.new(written: written, missing: presence ? presence.missing : [])
      end

      # releases.yml at +path+; true when it changed.
      def write_index(path, text)
        FileUtils.mkdir_p(File.dirname(path))
        AtomicFile.update(path, text)
      end

      # rock-osdeps.osdeps ({package: {default: deb}}) and rock-osdeps.inactive
      # of an Osdeps::Selection into +dir+; returns the path of the first.
      def write_selection(dir, selection)
        osdeps = selection.active.transform_values { |deb| { "default" => deb } }
        FileUtils.mkdir_p(dir)
        path = File.join(dir, "rock-osdeps.osdeps")
        AtomicFile.write(path, Yaml::Writer.dump(osdeps))
        AtomicFile.write(File.join(dir, "rock-osdeps.inactive"), Yaml::Writer.dump(selection.inactive))
        path
      end
    end
  end
end
