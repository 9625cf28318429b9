# frozen_string_literal: true

require_relative "../frozen"

module Relspec
  module Abi
    # Whether a package's new build left the interface its dependents
    # build against as it was (InterfaceCheck), with the evidence: what was
    # compared and what each comparison found. +package+: the autoproj
    # package; +version+ and +against+: the Debian versions of the new
    # build and of the build it replaces; +evidence+: [Evidence], sorted by
    # path.
    InterfaceVerdict = Struct.new(:package, :version, :against, :evidence, keyword_init: true)

    # The verdict's rules.
    class InterfaceVerdict
      # One comparison. +check+: :bytes (a file), :link (a link's target) or
      # :abi (a shared library's dumps, abidiff); +outcome+: :identical,
      # :unchanged, :compatible (only additions: still the same interface
      # for what was built against it), or one that changes it (:differs,
      # :changed, :incompatible, :added, :removed, :kind, :no_dump);
      # +detail+: abidiff's summary or what is missing.
      Evidence = Struct.new(:path, :check, :outcome, :detail, keyword_init: true) do
        def same?
          SAME.include?(outcome)
        end

        def to_s
          text = "#{path}: #{outcome.to_s.tr('_', ' ')}"
          detail.nil? || detail.empty? ? text : "#{text} (#{detail})"
        end
      end

      SAME = %i[identical unchanged compatible].freeze

      def self.of(package:, version:, against:, evidence:)
        Frozen.deep(new(package: package, version: version, against: against,
                        evidence: evidence.sort_by(&:path).map { |item| Frozen.deep(item) }))
      end

      # True when nothing a dependent builds against changed: its dependents
      # keep their binaries.
      def unchanged?
        evidence.all?(&:same?)
      end

      # What changed the interface, in path order (empty when unchanged).
      def changes
        evidence.reject(&:same?)
      end

      # One line: the verdict and its first reasons.
      def summary
        if unchanged?
          libraries = evidence.select { |item| item.check == :abi }
          "interface of #{package} unchanged from #{against}: #{evidence.size - libraries.size} files identical" +
            libraries.map { |item| ", #{File.basename(item.path)} #{item.outcome}" }.join
        else
          shown = changes.first(3).map(&:to_s)
          more = changes.size > 3 ? " and #{changes.size - 3} more" : ""
          "interface of #{package} changed from #{against}: #{shown.join('; ')}#{more}"
        end
      end
    end
  end
end
