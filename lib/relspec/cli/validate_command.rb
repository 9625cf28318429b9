# frozen_string_literal: true

require "json"
require_relative "../release_specs"
require_relative "friendly_errors"

module Relspec
  module CLI
    # `relspec validate [SPEC…]`: checks specs and their ancestors, offline.
    # Reads only; exit status 1 on any error.
    class ValidateCommand
      DEFAULT_DIR = "specs"

      def initialize(paths:, format:, out:, err:)
        @paths = paths
        @format = format
        @out = out
        @err = err
      end

      def call
        paths = @paths.empty? ? default_paths : @paths
        diagnostics = check(paths)
        @format == "json" ? report_json(paths, diagnostics) : report_text(paths, diagnostics)
        diagnostics.any?(&:error?) ? FriendlyErrors::EXIT_USER_ERROR : 0
      end

      private

      def default_paths
        library = ReleaseSpec::Library.new(DEFAULT_DIR)
        raise Error, "no #{DEFAULT_DIR}/ folder here: run from the project root or name the spec files" \
          unless File.directory?(DEFAULT_DIR)
        raise Error, "#{DEFAULT_DIR}/ holds no <release>.yml file" if library.names.empty?

        library.paths
      end

      # One library per folder, so parents are read once however many of
      # their children are checked.
      def check(paths)
        libraries = Hash.new { |hash, dir| hash[dir] = ReleaseSpec::Library.new(dir) }
        paths.flat_map { |path| ReleaseSpec::Resolution.of(libraries[File.dirname(path)], path).diagnostics }
             .uniq(&:to_s).sort_by(&:sort_key)
      end

      def report_text(paths, diagnostics)
        @err.puts(diagnostics.map(&:to_s)) unless diagnostics.empty?
        if diagnostics.any?(&:error?)
          @err.puts(Summary.of(diagnostics))
        else
          @out.puts("#{Summary.count(paths.size, 'spec')} valid#{warning_note(diagnostics)}: #{paths.join(' ')}")
        end
      end

      def warning_note(diagnostics)
        diagnostics.empty? ? "" : " (#{Summary.count(diagnostics.size, 'warning')})"
      end

      def report_json(paths, diagnostics)
        @out.puts(JSON.pretty_generate("valid" => diagnostics.none?(&:error?), "specs" => paths,
                                       "diagnostics" => diagnostics.map(&:to_h)))
      end
    end
  end
end
