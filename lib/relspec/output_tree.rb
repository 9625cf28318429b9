# frozen_string_literal: true

module Relspec
  # The folder compile writes and build and publish read (`--out`, build/ by
  # default): per release its orig tarball cache, and per target
  # <out>/<release>/<codename>-<arch>/ with one folder per source package,
  # plan.yml, build-results.yml, logs/ and results/. The one place these
  # paths are spelled.
  class OutputTree
    PLAN_FILE = "plan.yml"
    RESULTS_FILE = "build-results.yml"
    LOGS_DIR = "logs"
    RESULTS_DIR = "results"
    # The log of preparing a target's chroot, relative to its folder.
    PREPARE_LOG = "#{LOGS_DIR}/prepare.log".freeze

    # Relative to a target folder (what build-results.yml records and the
    # builder checks for links): a source's build log, its results folder and
    # the folder a build stages them in until it succeeds.
    def self.log_name(source)
      "#{LOGS_DIR}/#{source}.log"
    end

    def self.results_name(source)
      "#{RESULTS_DIR}/#{source}"
    end

    def self.staging_name(source)
      "#{RESULTS_DIR}/.#{source}.partial"
    end

    attr_reader :out, :release

    def initialize(out, release)
      @out = out
      @release = release
      freeze
    end

    def release_dir
      File.join(out, release)
    end

    # `relspec report`'s page and the logs it links to (Report).
    def report_dir
      File.join(release_dir, "report")
    end

    # Orig tarballs kept across compiles, by SHA256 (Debian::OrigCache).
    def orig_cache
      File.join(release_dir, ".orig")
    end

    # +target+: a Target.
    def target_dir(target)
      File.join(release_dir, target.dir_name)
    end

    def source_dir(target, deb_name)
      File.join(target_dir(target), deb_name)
    end

    def plan_file(target)
      File.join(target_dir(target), PLAN_FILE)
    end

    def results_file(target)
      File.join(target_dir(target), RESULTS_FILE)
    end

    def logs_dir(target)
      File.join(target_dir(target), LOGS_DIR)
    end
  end
end
