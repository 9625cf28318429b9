# frozen_string_literal: true

module Relspec
  module Plan
    # What happens to one package on one target:
    # - inherit: an ancestor's repository has it (+ancestor+, its +deb_name+ and +version+);
    # - build: it is built here (+deb_name+, +version+, +cause+);
    # - published: it was built here already and the release's repository holds it;
    # - system: a gem the target distribution itself provides (+deb_name+ ruby-…, +version+).
    # +version+: a Debian::PackageVersion for builds (settled by Versioning),
    # the index's version text otherwise; +debian_digest+ (builds): the
    # digest of the debian/ the version was settled from; +depends+
    # (builds): the packages whose decisions on this target its debian/
    # names (its direct dependencies), sorted: a change of one of them is
    # what moves the build's revision when its own source did not change.
    # +cutoff+ (builds): a CutoffCandidate when only dependencies rebuilt
    # now moved it, else nil. +kept+ (published): why the early cutoff
    # kept its version when its dependencies were rebuilt (the history's
    # word, docs/abi.md), else nil.
    Decision = Struct.new(:package, :kind, :deb_name, :version, :ancestor, :cause, :debian_digest, :depends, :cutoff,
                          :kept, keyword_init: true) do
      def inherit?
        kind == :inherit
      end

      def build?
        kind == :build
      end

      def published?
        kind == :published
      end

      def system?
        kind == :system
      end

      def to_h
        entry = { "decision" => kind.to_s, "deb" => deb_name, "version" => version&.to_s }
        entry["from"] = ancestor if ancestor
        entry["causes"] = cause.chain if cause
        entry["debian_digest"] = debian_digest if debian_digest
        entry
      end
    end
  end
end
