# frozen_string_literal: true

module Relspec
  module Spec
    # A target distribution as autoproj's osdeps name it: a type (ubuntu
    # inherits Debian's package names, so it is keyed "ubuntu,debian") and the
    # labels autoproj matches against the running system.
    # +archive+: where the distribution's own packages can be read (a
    # repository entry with components), or nil.
    Distribution = Struct.new(:codename, :type, :labels, :archive, keyword_init: true) do
      def self.define(codename, type, labels, archive: nil)
        new(codename: codename, type: type, labels: labels.map(&:to_s).freeze, archive: archive&.freeze).freeze
      end

      def osdeps_type_key
        type == "ubuntu" ? "ubuntu,debian" : "debian"
      end

      # The labels an osdeps entry is keyed by. "default" is left out: autoproj
      # adds "default" to every system's versions, so an entry keyed with it
      # would also resolve on distributions the release does not target, and
      # on Debian both the "ubuntu,debian" and the "debian" entry would match,
      # giving two names when a package differs between the two.
      def osdeps_labels_key
        (labels - ["default"]).join(",")
      end
    end

    # The distributions Rock releases have targeted; specs may add or override
    # entries with `distributions:`.
    module Distributions
      TYPES = %w[ubuntu debian].freeze

      BUILTIN = [
        Distribution.define("xenial", "ubuntu", %w[16.04 xenial xerus default]),
        Distribution.define("bionic", "ubuntu", %w[18.04 bionic beaver default]),
        Distribution.define("focal", "ubuntu", %w[20.04 focal fossa default]),
        Distribution.define("jammy", "ubuntu", %w[22.04 jammy jellyfish default]),
        Distribution.define("noble", "ubuntu", %w[24.04 noble numbat default]),
        Distribution.define("stretch", "debian", %w[9 stretch default]),
        Distribution.define("buster", "debian", %w[10 buster default]),
        Distribution.define("bullseye", "debian", %w[11 bullseye default]),
        Distribution.define("bookworm", "debian", %w[12 bookworm default])
      ].to_h { |d| [d.codename, d] }.freeze

      # Built-ins overlaid with a spec's own definitions ({codename =>
      # {"type", "labels", "archive"}}); a built-in keeps what an override leaves out.
      def self.with_overrides(definitions)
        own = (definitions || {}).to_h do |codename, definition|
          known = BUILTIN[codename]
          [codename, Distribution.define(codename, definition["type"] || known&.type,
                                         definition["labels"] || known&.labels || [], archive: definition["archive"])]
        end
        BUILTIN.merge(own).freeze
      end
    end
  end
end
