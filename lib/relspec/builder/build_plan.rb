# frozen_string_literal: true

require "yaml"
require_relative "../error"

module Relspec
  module Builder
    # One target's plan.yml, as `relspec compile` wrote it: the source
    # packages to build in dependency order, each with the sources of the
    # same release it needs built first. Packages the release's repository
    # already holds at their version are not in it (compile decided
    # "published" for them).
    class BuildPlan
      FILE = "plan.yml"
      # Source names become folder names (results/<source>, logs/<source>.log).
      SOURCE_NAME = /\A[a-z0-9][a-z0-9.+-]*\z/

      Entry = Struct.new(:package, :source, :version, :dsc, :build_depends, keyword_init: true)

      attr_reader :dir, :release, :target, :entries

      # +dir+: <out>/<release>/<codename>-<arch>.
      def self.read(dir)
        path = File.join(dir, FILE)
        raise BuildError, "#{path} does not exist: run `relspec compile` first" unless File.file?(path)

        data = YAML.safe_load(File.read(path))
        new(dir, data, path)
      rescue Psych::SyntaxError => e
        raise BuildError, "#{path}:#{e.line}: cannot be read (#{e.problem}); run `relspec compile` again"
      end

      def initialize(dir, data, path)
        @dir = dir
        raise BuildError, "#{path}: not a plan written by relspec compile" unless data.is_a?(Hash) && data["builds"].is_a?(Array)

        @release = data["release"].to_s
        @target = data["target"].to_s
        @entries = data["builds"].map { |build| entry(build, path) }.freeze
        freeze
      end

      def codename
        target.split("/").first
      end

      def arch
        target.split("/").last
      end

      def dsc_path(entry)
        File.join(dir, entry.dsc)
      end

      private

      def entry(build, path)
        source = build["source"].to_s
        raise BuildError, "#{path}: invalid source name #{source.inspect}" unless source.match?(SOURCE_NAME)

        Entry.new(package: build["package"].to_s, source: source, version: build["version"].to_s,
                  dsc: build["dsc"].to_s, build_depends: Array(build["build_depends"]).map(&:to_s).freeze).freeze
      end
    end
  end
end
