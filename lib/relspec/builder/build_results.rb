# frozen_string_literal: true

require "yaml"
require "digest"
require_relative "../atomic_file"
require_relative "../display_path"
require_relative "../yaml/located_document"
require_relative "../yaml/field_reader"
require_relative "../apt/version"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../output_tree"
require_relative "../debian_name"

module Relspec
  module Builder
    # <out>/<release>/<codename>-<arch>/build-results.yml: what each source
    # package's last build gave (docs/build.md). One class holds the writer
    # (`relspec build`, after every package, atomically, so a killed run
    # keeps every finished package) and the strict reader (build on resume,
    # publish): every key known, every value of its type, every path inside
    # the target folder. A damaged file is an InvalidInput naming file:line,
    # never "nothing built" and never a crash: publishing from a guess could
    # put the wrong bytes into a repository, where they stay forever.
    class BuildResults
      FILE_NAME = OutputTree::RESULTS_FILE
      FORMAT_KEY = "relspec_build_results"
      FORMAT_VERSION = 1
      ROOT_KEYS = [FORMAT_KEY, "release", "target", "backend", "packages"].freeze
      PACKAGE_KEYS = %w[package version dsc_sha256 status duration log reason files interface cutoff].freeze
      CUTOFF_KEYS = %w[keeps verdict reason evidence].freeze
      CUTOFF_VERDICTS = %w[keep rebuild].freeze
      FILE_KEYS = %w[name sha256 size].freeze
      INTERFACE_KEYS = %w[against verdict compared changes held].freeze
      INTERFACE_VERDICTS = %w[unchanged changed].freeze
      # The changes a record keeps of a verdict: the first ones say why.
      INTERFACE_CHANGES = 20
      STATUSES = %w[built kept failed skipped published].freeze
      SHA256 = /\A[0-9a-f]{64}\z/
      HINT = "build-results.yml is written by `relspec build`: delete it and run `relspec build` again for this target"

      # One produced file, +name+ relative to the target folder.
      Produced = Struct.new(:name, :sha256, :size, keyword_init: true) do
        def self.of(dir, name)
          full = File.join(dir, name)
          new(name: name, sha256: Digest::SHA256.file(full).hexdigest, size: File.size(full)).freeze
        end

        def to_h
          { "name" => name, "sha256" => sha256, "size" => size }
        end

        # Still there with the bytes recorded.
        def intact?(dir)
          path = File.join(dir, name)
          File.file?(path) && File.size(path) == size && Digest::SHA256.file(path).hexdigest == sha256
        end
      end

      # The early cutoff's verdict on a build (Abi::InterfaceCheck), as
      # the record keeps it: +against+ the version of the build it
      # replaced, +verdict+ "unchanged" or "changed", +compared+ how many
      # installed files were compared, +changes+ the first of what changed
      # (Evidence#to_s), +held+ the version the release's repository holds
      # when it is another than +against+ (a build made and not published
      # was compared: no baseline for the early cutoff), else nil.
      # docs/abi.md, "Early cutoff".
      Interface = Struct.new(:against, :verdict, :compared, :changes, :held, keyword_init: true) do
        def self.of(verdict)
          new(against: verdict.against, verdict: verdict.unchanged? ? "unchanged" : "changed",
              compared: verdict.evidence.size,
              changes: verdict.changes.first(INTERFACE_CHANGES).map(&:to_s).freeze).freeze
        end

        def unchanged?
          verdict == "unchanged"
        end

        def to_h
          { "against" => against, "verdict" => verdict, "compared" => compared, "changes" => changes, "held" => held }.compact
        end
      end

      # What the early cutoff decided for a candidate of the plan
      # (BuildPlan::Cutoff): "keep" its published version +keeps+ (the
      # record's status is then "kept": not built, the repository's build
      # stays) or "rebuild", with the +reason+ and, for a keep, the
      # +evidence+: one line per package of the candidate's closure whose
      # interface was compared (docs/abi.md).
      Cutoff = Struct.new(:keeps, :verdict, :reason, :evidence, keyword_init: true) do
        def keep?
          verdict == "keep"
        end

        # The reason with the evidence, on one line (why, report, diff).
        def summary
          evidence.nil? || evidence.empty? ? reason : "#{reason} (#{evidence.join('; ')})"
        end

        def to_h
          { "keeps" => keeps, "verdict" => verdict, "reason" => reason,
            "evidence" => evidence.nil? || evidence.empty? ? nil : evidence }.compact
        end
      end

      # One source package's result. +files+: Produced, empty unless built;
      # +dsc_sha256+: the SHA256 of the .dsc it was built from (nil in
      # results written before relspec recorded it: such a build is done
      # again, since a source rewritten at the same version is another one).
      # +interface+: an Interface when the build replaced an earlier one
      # of another version, else nil.
      Record = Struct.new(:source, :package, :version, :dsc_sha256, :status, :duration, :log, :reason, :files,
                          :interface, :cutoff, keyword_init: true) do
        def built?
          status == "built"
        end

        # Kept by the early cutoff: not built, its published build stays.
        def kept?
          status == "kept"
        end

        # The version of the build whose files the record lists: a kept
        # record lists the files of the build it keeps (when the target
        # folder had them), so that the next build is compared with them.
        def files_version
          kept? ? cutoff.keeps : version
        end

        def to_h
          { "package" => package, "version" => version, "dsc_sha256" => dsc_sha256, "status" => status,
            "duration" => duration,
            "log" => log, "reason" => reason, "files" => files.empty? ? nil : files.map(&:to_h),
            "interface" => interface&.to_h, "cutoff" => cutoff&.to_h }.compact
        end
      end

      attr_reader :path, :release, :target, :backend

      # The results in target folder +dir+, empty when there are none yet.
      def self.load(dir, release:, target:)
        path = File.join(dir, FILE_NAME)
        return new(path, release, target) unless File.exist?(path)

        read(DisplayPath.of(path), release: release, target: target)
      end

      # The results at +path+, for +release+ and +target+ (a Target).
      def self.read(path, release:, target:)
        from(Yaml::LocatedDocument.load(path), release, target)
      end

      def self.parse(text, file:, release:, target:)
        from(Yaml::LocatedDocument.parse(text, file: file), release, target)
      end

      def self.from(document, release, target)
        reader = Reader.new(document, release, target.to_s)
        new(document.file, release, target, records: reader.records, backend: reader.backend)
      end
      private_class_method :from

      def initialize(path, release, target, records: [], backend: nil)
        @path = path
        @release = release
        @target = target.to_s
        @backend = backend
        @records = records.to_h { |record| [record.source, record] }
      end

      def entries
        @records.values.sort_by(&:source)
      end

      def built
        entries.select(&:built?)
      end

      def [](source)
        @records[source]
      end

      # True when +source+ was built at +version+ from the .dsc whose SHA256
      # is +dsc_sha256+, and every file it produced is still there with the
      # bytes recorded.
      def built?(source, version, dsc_sha256)
        record = @records[source]
        !!record&.built? && same_source?(record, version, dsc_sha256) &&
          record.files.all? { |file| file.intact?(File.dirname(@path)) }
      end

      # True when the early cutoff kept +source+ for this +version+ and
      # .dsc (an earlier run decided it: nothing to build).
      def kept?(source, version, dsc_sha256)
        record = @records[source]
        !!record&.kept? && same_source?(record, version, dsc_sha256)
      end

      def record(record)
        @records[record.source] = record
      end

      # The results of +sources+ only (what the current plan builds), as
      # another BuildResults of the same file; the file itself keeps the
      # others, so that narrowing a plan and widening it again builds
      # nothing twice.
      def within(sources)
        wanted = sources.to_h { |source| [source, true] }
        self.class.new(@path, @release, @target, records: @records.values.select { |record| wanted[record.source] },
                                                 backend: @backend)
      end

      # #within, keeping only records at the version +versions+ (source =>
      # planned version) names: what publish may take. A record of an
      # earlier version of a planned package (its rebuild not done yet) is
      # not the release's, and counts as not built.
      def at_versions(versions)
        self.class.new(@path, @release, @target, backend: @backend,
                                                 records: @records.values.select { |record| versions[record.source] == record.version })
      end

      def same_source?(record, version, dsc_sha256)
        record.version == version && !dsc_sha256.nil? && record.dsc_sha256 == dsc_sha256
      end
      private :same_source?

      def write(backend:)
        @backend = backend
        data = { FORMAT_KEY => FORMAT_VERSION, "release" => @release, "target" => @target, "backend" => backend,
                 "packages" => entries.to_h { |record| [record.source, record.to_h] } }
        AtomicFile.write(@path, YAML.dump(data))
      end

      # The strict reading of one document.
      class Reader
        attr_reader :records, :backend

        def initialize(document, release, target)
          @fields = Yaml::FieldReader.new(document, rule: "build-results", what: "the build results", hint: HINT)
          @document = document
          read(release, target)
        end

        private

        def read(release, target)
          data = @fields.root
          fail_at([FORMAT_KEY], "unknown format #{data[FORMAT_KEY].inspect} (this relspec reads #{FORMAT_VERSION})") \
            unless data[FORMAT_KEY] == FORMAT_VERSION
          @fields.known_keys(data, [], ROOT_KEYS)
          @fields.expect(data, ["release"], release)
          @fields.expect(data, ["target"], target)
          @backend = @fields.text(data, ["backend"])
          @records = @fields.mapping(data, ["packages"]).map { |source, record| record(source, record) }.freeze
        end

        def record(source, fields)
          path = ["packages", source]
          fail_at(path, "#{source.inspect} is not a Debian source package name") unless DebianName.valid?(source)
          fail_at(path, "packages.#{source} must be a mapping") unless fields.is_a?(Hash)
          @fields.known_keys(fields, path, PACKAGE_KEYS)
          status = @fields.text(fields, path + ["status"])
          fail_at(path + ["status"], "status #{status.inspect} is not one of #{STATUSES.join(', ')}") unless STATUSES.include?(status)
          files = files(fields, path + ["files"])
          fail_at(path + ["files"], "a built package lists the files it produced") if status == "built" && files.empty?
          cutoff = cutoff(fields, path + ["cutoff"])
          fail_at(path + ["status"], "a kept package names the early cutoff's keep (cutoff: verdict keep)") \
            if status == "kept" && !cutoff&.keep?
          Record.new(source: source, package: @fields.text(fields, path + ["package"]),
                     version: version(fields, path + ["version"]), dsc_sha256: dsc_sha256(fields, path + ["dsc_sha256"]),
                     status: status,
                     duration: duration(fields, path + ["duration"]),
                     log: fields["log"].nil? ? nil : @fields.plain_path(fields, path + ["log"]),
                     reason: @fields.optional_text(fields, path + ["reason"]), files: files.freeze,
                     interface: interface(fields, path + ["interface"]), cutoff: cutoff).freeze
        end

        def cutoff(fields, path)
          data = fields[path.last]
          return nil if data.nil?

          fail_at(path, "#{@fields.describe(path)} must be a mapping of keeps, verdict and reason") unless data.is_a?(Hash)
          @fields.known_keys(data, path, CUTOFF_KEYS)
          verdict = @fields.text(data, path + ["verdict"])
          fail_at(path + ["verdict"], "verdict #{verdict.inspect} is not one of #{CUTOFF_VERDICTS.join(', ')}") \
            unless CUTOFF_VERDICTS.include?(verdict)
          evidence = (data["evidence"].nil? ? [] : @fields.list(data, path + ["evidence"], of: "evidence")).each_with_index.map do |line, index|
            fail_at(path + ["evidence", index], "evidence must be text") unless line.is_a?(String)
            line
          end
          Cutoff.new(keeps: version(data, path + ["keeps"]), verdict: verdict, reason: @fields.text(data, path + ["reason"]),
                     evidence: evidence.freeze).freeze
        end

        def interface(fields, path)
          return nil if fields[path.last].nil?

          data = fields[path.last]
          fail_at(path, "#{@fields.describe(path)} must be a mapping of against, verdict, compared and changes") \
            unless data.is_a?(Hash)
          @fields.known_keys(data, path, INTERFACE_KEYS)
          verdict = @fields.text(data, path + ["verdict"])
          fail_at(path + ["verdict"], "verdict #{verdict.inspect} is not one of #{INTERFACE_VERDICTS.join(', ')}") \
            unless INTERFACE_VERDICTS.include?(verdict)
          compared = data["compared"]
          fail_at(path + ["compared"], "compared must be a number of files") unless compared.is_a?(Integer) && compared >= 0
          changes = @fields.list(data, path + ["changes"], of: "changes").each_with_index.map do |change, index|
            fail_at(path + ["changes", index], "a change must be text") unless change.is_a?(String)
            change
          end
          held = data["held"].nil? ? nil : version(data, path + ["held"])
          Interface.new(against: version(data, path + ["against"]), verdict: verdict, compared: compared,
                        changes: changes.freeze, held: held).freeze
        end

        def files(fields, path)
          @fields.list(fields, path, of: "files").each_with_index.map do |file, index|
            at = path + [index]
            fail_at(at, "#{@fields.describe(at)} must be a mapping of name, sha256 and size") unless file.is_a?(Hash)
            @fields.known_keys(file, at, FILE_KEYS)
            name = @fields.plain_path(file, at + ["name"])
            sha256 = @fields.text(file, at + ["sha256"])
            fail_at(at + ["sha256"], "sha256 must be 64 lowercase hex digits") unless sha256.match?(SHA256)
            size = file["size"]
            fail_at(at + ["size"], "size must be a number of bytes") unless size.is_a?(Integer) && size >= 0
            Produced.new(name: name, sha256: sha256, size: size).freeze
          end
        end

        def dsc_sha256(fields, path)
          return nil if fields[path.last].nil?

          value = @fields.text(fields, path)
          fail_at(path, "dsc_sha256 must be 64 lowercase hex digits") unless value.match?(SHA256)
          value
        end

        def duration(hash, path)
          value = hash[path.last]
          return nil if value.nil?

          fail_at(path, "#{@fields.describe(path)} must be a number of seconds") unless value.is_a?(Numeric) && value >= 0

          value
        end

        def version(hash, path)
          value = @document.raw(path) || @fields.text(hash, path)
          fail_at(path, "#{@fields.describe(path)} must be text") unless value.is_a?(String)
          fail_at(path, "invalid Debian version #{value.inspect}") unless Apt::Version.valid?(value)

          value
        end

        def fail_at(path, message)
          @fields.fail_at(path, message)
        end
      end
    end
  end
end
