# frozen_string_literal: true

require "yaml"
require "digest"
require_relative "../atomic_file"

module Relspec
  module Builder
    # A target's build-results.yml: what each source package's last build
    # gave (the format `relspec publish` reads; docs/build.md). Written
    # atomically after every package, so a killed run leaves the state of
    # every finished package, and the next run goes on from there.
    class Results
      FILE = "build-results.yml"
      FORMAT = 1
      STATUSES = %w[built failed skipped published].freeze

      # +files+: [{"name", "sha256", "size"}], names relative to the target folder.
      Record = Struct.new(:package, :version, :status, :duration, :log, :reason, :files, keyword_init: true) do
        def to_h
          { "package" => package, "version" => version, "status" => status, "duration" => duration,
            "log" => log, "reason" => reason, "files" => files }.compact
        end
      end

      attr_reader :dir, :records, :backend

      def self.read(dir)
        path = File.join(dir, FILE)
        data = File.file?(path) ? YAML.safe_load(File.read(path)) : nil
        records = {}
        if data.is_a?(Hash) && data["relspec_build_results"] == FORMAT && data["packages"].is_a?(Hash)
          data["packages"].each do |source, fields|
            next unless fields.is_a?(Hash) && STATUSES.include?(fields["status"])

            records[source] = Record.new(**fields.slice(*Record.members.map(&:to_s)).transform_keys(&:to_sym))
          end
        end
        new(dir, records, backend: data.is_a?(Hash) ? data["backend"] : nil)
      rescue Psych::Exception
        new(dir, {}) # an unreadable record only costs rebuilding; it never blocks a build
      end

      # +backend+: the backend of the run that wrote the file.
      def initialize(dir, records = {}, backend: nil)
        @dir = dir
        @records = records
        @backend = backend
      end

      # True when +source+ was built at +version+ and every file it produced
      # is still there with the bytes recorded.
      def built?(source, version)
        record = @records[source]
        return false unless record&.status == "built" && record.version == version && record.files.is_a?(Array)

        record.files.all? do |file|
          path = File.join(dir, file["name"].to_s)
          File.file?(path) && File.size(path) == file["size"] && Digest::SHA256.file(path).hexdigest == file["sha256"]
        end
      end

      def [](source)
        @records[source]
      end

      def record(source, record)
        @records[source] = record
      end

      def write(release:, target:, backend:)
        packages = @records.sort.to_h { |source, record| [source, record.to_h] }
        data = { "relspec_build_results" => FORMAT, "release" => release, "target" => target, "backend" => backend,
                 "packages" => packages }
        AtomicFile.write(File.join(dir, FILE), YAML.dump(data))
      end

      # {name, sha256, size} of a produced file, +path+ below the target folder.
      def self.file_entry(dir, path)
        full = File.join(dir, path)
        { "name" => path, "sha256" => Digest::SHA256.file(full).hexdigest, "size" => File.size(full) }
      end
    end
  end
end
