# frozen_string_literal: true

require_relative "lock"
require_relative "source_record"
require_relative "history"
require_relative "../yaml/located_document"
require_relative "../yaml/quick_document"
require_relative "../apt/version"
require_relative "../debian/package_version"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Plan
    # Reads a lock file back into a Lock, as strictly as LockGenerator
    # writes it: every key known, every value of its type, every version a
    # valid Debian version. A lock relspec cannot read is a LockError naming
    # file:line, never an empty lock, because the lock holds the history
    # that decides revisions: losing it silently would give a second build
    # of a version the repository already has.
    #
    # Format 1 locks (relspec before the history section) are read too: their
    # recorded builds become the history.
    class LockParser
      ROOT_KEYS = %w[relspec_lock release spec_digest ancestors packages targets history warnings notes].freeze
      ENTRY_KEYS = Lock::Entry::FIELDS
      PACKAGE_KEYS = SourceRecord.fields.freeze
      DECISIONS = Lock::Entry::DECISIONS
      DIGEST = /\A[0-9a-f]{64}\z/
      DISCARD_HINT = "fix the file (it is in git), or run again with --discard-lock to start over " \
                     "(the release's repository then keeps revisions from being given twice)"

      # The Lock at +path+, or nil when there is none. +release+: the release
      # the lock must belong to.
      def self.read(path, release:)
        return nil unless File.exist?(path)
        # LocatedDocument refuses what is not a plain file of a sane size.
        return new(Yaml::LocatedDocument.load(path), release).lock unless File.file?(path) && File.size(path) <= Yaml::Limits::MAX_BYTES

        parse(File.binread(path), file: path, release: release)
      end

      # Locks are read without positions first (half the time; `relspec diff`
      # reads two of 400 packages); only a lock with an error is read again
      # with them, so that the error still names file:line.
      def self.parse(text, file:, release:)
        quick = Yaml::QuickDocument.parse(text)
        if quick
          begin
            return new(quick, release).lock
          rescue LockError
            nil # read again below, to say where
          end
        end
        new(Yaml::LocatedDocument.parse(text, file: file), release).lock
      end

      def initialize(document, release)
        @document = document
        @release = release
      end

      def lock
        unless @document.ok?
          raise(LockError, @document.diagnostics.select(&:error?).map { |d| Diagnostic.error("lock", d.message, location: d.location, hint: DISCARD_HINT) })
        end

        data = @document.data
        fail_at([], "the lock is empty or not a mapping") unless data.is_a?(Hash)
        format = data[Lock::FORMAT_KEY]
        unless [1, Lock::FORMAT_VERSION].include?(format)
          fail_at([Lock::FORMAT_KEY], "unknown lock format #{format.inspect} (this relspec reads 1 and #{Lock::FORMAT_VERSION})")
        end
        known_keys(data, [], ROOT_KEYS)
        # LockGenerator writes every section of format 2: one missing means
        # the file was cut short, and reading it as "no targets" would
        # show a diff or a plan less than the truth.
        missing = format == Lock::FORMAT_VERSION ? ROOT_KEYS - data.keys : []
        fail_at([], "the lock has no #{missing.first}: section (cut short?)") unless missing.empty?
        release = string(data, ["release"])
        fail_at(["release"], "the lock is of release #{release}, not #{@release}") if @release && release != @release

        Lock.new(release: release, spec_digest: digest(data, ["spec_digest"]), ancestors: ancestors(data),
                 packages: packages(data), targets: targets(data, format), history: history(data, format),
                 warnings: strings(data, ["warnings"]), notes: strings(data, ["notes"]))
      end

      private

      def ancestors(data)
        mapping(data["ancestors"], ["ancestors"]).to_h do |name, codenames|
          [name, mapping(codenames, ["ancestors", name]).to_h { |codename, _| [codename, digest(codenames, ["ancestors", name, codename])] }]
        end
      end

      def packages(data)
        mapping(data["packages"], ["packages"]).to_h do |name, record|
          path = ["packages", name]
          mapping(record, path)
          known_keys(record, path, PACKAGE_KEYS)
          [name, SourceRecord.from(record.to_h { |key, _| [key, string(record, path + [key])] })]
        end
      end

      def targets(data, format)
        mapping(data["targets"], ["targets"]).to_h do |target, entries|
          [target, mapping(entries, ["targets", target]).to_h do |name, entry|
            [name, entry(entry, ["targets", target, name], format)]
          end]
        end
      end

      def entry(entry, path, format)
        mapping(entry, path)
        known_keys(entry, path, format == 1 ? ENTRY_KEYS + ["last_build"] : ENTRY_KEYS)
        decision = string(entry, path + ["decision"])
        fail_at(path + ["decision"], "unknown decision #{decision.inspect} (one of #{DECISIONS.join(', ')})") unless DECISIONS.include?(decision)

        causes = entry["causes"].nil? ? nil : strings(entry, path + ["causes"])
        depends = entry["depends"].nil? ? nil : strings(entry, path + ["depends"])
        version = optional_version(entry, path + ["version"])
        # every decision but unavailable names the version it stands for
        fail_at(path + ["version"], "#{describe(path)}: a #{decision} decision needs a version") if version.nil? && decision != "unavailable"

        Lock::Entry.new(decision: decision, deb: optional_string(entry, path + ["deb"]),
                        version: version, from: optional_string(entry, path + ["from"]),
                        causes: causes, depends: depends,
                        debian_digest: entry["debian_digest"] && digest(entry, path + ["debian_digest"]),
                        kept: optional_string(entry, path + ["kept"])).freeze
      end

      def history(data, format)
        return history_of_format1(data) if format == 1

        builds = mapping(data["history"], ["history"]).to_h do |target, packages|
          [target, mapping(packages, ["history", target]).to_h do |package, upstreams|
            [package, mapping(upstreams, ["history", target, package]).to_h do |upstream, build|
              path = ["history", target, package, upstream]
              fail_at(path, "invalid upstream version #{upstream.inspect}") unless upstream.match?(/\A[0-9][A-Za-z0-9.+~]*\z/)
              mapping(build, path)
              known_keys(build, path, %w[revision debian_digest kept])
              revision = build["revision"]
              fail_at(path + ["revision"], "revision must be a positive whole number") unless revision.is_a?(Integer) && revision.positive?
              [upstream, History::Build.new(revision: revision, debian_digest: digest(build, path + ["debian_digest"]),
                                            kept: optional_string(build, path + ["kept"]))]
            end]
          end]
        end
        History.new(builds)
      end

      # Format 1 kept builds in the decisions (and last_build for packages
      # not built that time).
      def history_of_format1(data)
        builds = mapping(data["targets"], ["targets"]).flat_map do |target, entries|
          mapping(entries, ["targets", target]).flat_map do |name, entry|
            [entry, entry.is_a?(Hash) && entry["last_build"]].filter_map do |build|
              next unless build.is_a?(Hash) && build["debian_digest"]

              version = Debian::PackageVersion.parse(build["version"])
              version && [target, name, version, build["debian_digest"]]
            end
          end
        end
        History.empty.with_all(builds)
      end

      # +value+ (at +path+) as a Hash; a missing top-level section is empty.
      def mapping(value, path)
        return {} if value.nil? && path.size == 1

        fail_at(path, "#{describe(path)} must be a mapping") unless value.is_a?(Hash)

        # every key of a lock is text (a name, a target, a field): a bare
        # 7 or true is not what relspec writes
        odd = value.keys.find { |key| @document.typed_key?(path + [key]) }
        fail_at(path + [odd], "the key #{odd} in #{describe(path)} must be text (relspec writes it quoted: \"#{odd}\")", key: true) if odd

        value
      end

      def known_keys(hash, path, keys)
        unknown = hash.keys - keys
        fail_at(path + [unknown.first], "unknown key #{unknown.first.inspect} in #{describe(path)}") unless unknown.empty?
      end

      # Text as relspec writes it: a number, true or null where text
      # belongs (a commit 1234567, a version 1.10 that would read as 1.1)
      # is not what it wrote, whatever it may have meant.
      def string(hash, path)
        value = hash[path.last]
        fail_at(path, "#{describe(path)} must be text, not #{kind_of(value, path)}") unless value.is_a?(String)

        value
      end

      def kind_of(value, path)
        written = @document.raw(path) || value.to_s
        case value
        when nil then "null"
        when Numeric then "the number #{written}"
        when true, false then written
        else "a #{value.is_a?(Hash) ? 'mapping' : 'list'}"
        end
      end

      def optional_string(hash, path)
        hash[path.last].nil? ? nil : string(hash, path)
      end

      def strings(hash, path)
        list = hash[path.last]
        return [] if list.nil?

        fail_at(path, "#{describe(path)} must be a list of text") unless list.is_a?(Array) && list.all?(String)

        list
      end

      def digest(hash, path)
        value = string(hash, path)
        fail_at(path, "#{describe(path)} must be a SHA256 digest (64 hex digits)") unless value.match?(DIGEST)

        value
      end

      def optional_version(hash, path)
        return nil if hash[path.last].nil?

        text = string(hash, path)
        Apt::Version.parse(text)
        text
      rescue ArgumentError
        fail_at(path, "invalid Debian version #{text.inspect}")
      end

      def describe(path)
        path.empty? ? "the lock" : path.join(".")
      end

      # +key+: point at the key of +path+ rather than at its value.
      def fail_at(path, message, key: false)
        location = key ? @document.key_location(path.compact) : @document.location(path.compact)
        raise LockError, [Diagnostic.error("lock", "cannot read the lock: #{message}", location: location, hint: DISCARD_HINT)]
      end
    end
  end
end
