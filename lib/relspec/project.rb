# frozen_string_literal: true

require_relative "display_path"

module Relspec
  # The folders of a release project (the repository that holds the specs):
  # specs/ and releases/ with releases.yml and per
  # release its lock.yml and osdeps/. +root+ is the folder holding specs/;
  # paths come back as the user would write them ("releases/r/lock.yml",
  # not "./releases/r/lock.yml"), since relspec prints them.
  # (overlays/<package>/ is Debian::Overlay's: its paths are the ones
  # overlay diagnostics print.)
  class Project
    attr_reader :root

    # The project of the spec file at +spec_path+: the folder above the
    # spec's folder.
    def self.of_spec(spec_path)
      new(DisplayPath.of(File.dirname(File.expand_path(spec_path), 2)))
    end

    def initialize(root)
      @root = root
      freeze
    end

    def specs_dir
      join("specs")
    end

    # The rock-osdeps package set's release index.
    def release_index
      join("releases", "releases.yml")
    end

    def lock_path(release)
      join("releases", release, "lock.yml")
    end

    def osdeps_dir(release)
      join("releases", release, "osdeps")
    end

    private

    def join(*parts)
      File.join(root, *parts).delete_prefix("./")
    end
  end
end
