# frozen_string_literal: true

require_relative "../error"
require_relative "architectures"
require_relative "values/archive"

module Relspec
  module ReleaseSpec
    # A target distribution as autoproj's osdeps name it: a type (ubuntu
    # inherits Debian's package names, so it is keyed "ubuntu,debian") and the
    # labels autoproj matches against the running system.
    # +archive+: where the distribution's own packages can be read (an
    # Archive: a repository entry with components), or nil. +debhelper_compat+: the
    # debhelper compatibility level generated debian/ folders use there (the
    # highest its debhelper supports; docs/compile.md lists the sources).
    # +ruby+: the "major.minor" of the distribution's Ruby (autoproj loads
    # `.osdeps-ruby<major><minor>` files for it), or nil when unknown;
    # +ruby_release+: its upstream version ("3.1.2", what the gems relspec
    # packages must run on: grape 4.1 needs Ruby >= 3.3.1), or nil.
    Distribution = Struct.new(:codename, :type, :labels, :archive, :debhelper_compat, :ruby, :ruby_release,
                              keyword_init: true) do
      def self.define(codename, type, labels, archive: nil, debhelper_compat: DEFAULT_DEBHELPER_COMPAT, ruby: nil,
                      ruby_release: nil)
        new(codename: codename, type: type, labels: labels.map(&:to_s).freeze, archive: Archive.from(archive),
            debhelper_compat: debhelper_compat, ruby: ruby, ruby_release: ruby_release).freeze
      end

      # The distribution's Ruby as a path (/usr/bin/ruby3.3, from the
      # ruby3.3 package); /usr/bin/ruby (the ruby package's) when unknown.
      def ruby_executable
        ruby ? "/usr/bin/ruby#{ruby}" : "/usr/bin/ruby"
      end

      # autoproj's keyword for the distribution's Ruby ("ruby31"), or nil.
      def ruby_version_keyword
        ruby && "ruby#{ruby.delete('.')}"
      end

      # Where a package built for +arch+ that installs Ruby code the way the
      # distribution's Ruby lays it out (a CMake project asking RbConfig for
      # rubylibdir and archdir, as typelib's bindings do) puts it, relative to
      # its prefix; empty when the distribution's Ruby is not known. Ruby
      # "3.1" keeps its libraries in lib/ruby/3.1.0.
      def ruby_install_dirs(arch)
        return [] unless ruby

        abi = "#{ruby}.0"
        tuple = Architectures::MULTIARCH[arch]
        ["lib/ruby/#{abi}", *(tuple && "lib/#{tuple}/ruby/#{abi}")]
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

    # Distributions relspec does not know get the compat level of current
    # debhelper unless their definition says otherwise.
    DEFAULT_DEBHELPER_COMPAT = 13

    # The distributions Rock releases have targeted; specs may add or override
    # entries with `distributions:`.
    module Distributions
      TYPES = %w[ubuntu debian].freeze

      # debhelper of each distribution (docs/compile.md): xenial 9.20160115,
      # stretch 10.2.5, bionic 11.1.6, buster 12.1.1, focal 12.10,
      # bullseye 13.3.4, jammy 13.6, bookworm 13.11.4, noble 13.14.1,
      # trixie 13.24.2 (compat 14 is still experimental there). Their Ruby
      # (the ruby package's default): xenial 2.3, stretch 2.3, bionic 2.5,
      # buster 2.5, focal 2.7, bullseye 2.7, jammy 3.0, bookworm 3.1,
      # noble 3.2, trixie 3.3; the upstream version of that Ruby in each
      # archive (its rubyX.Y package; a stable release keeps it): xenial
      # 2.3.1, stretch 2.3.3, bionic 2.5.1, buster 2.5.5, focal 2.7.0,
      # bullseye 2.7.4, jammy 3.0.2, bookworm 3.1.2, noble 3.2.3, trixie
      # 3.3.8. Labels: what autoproj reads of /etc/os-release
      # (VERSION_ID, then the words of VERSION: "13 (trixie)"), plus
      # "default". Debian testing (forky) is not built in: its os-release has
      # no version and its /etc/debian_version says "forky/sid", so autoproj
      # names it "unstable, sid", and its Ruby and debhelper still move.
      BUILTIN = [
        Distribution.define("xenial", "ubuntu", %w[16.04 xenial xerus default], debhelper_compat: 9, ruby: "2.3", ruby_release: "2.3.1"),
        Distribution.define("bionic", "ubuntu", %w[18.04 bionic beaver default], debhelper_compat: 11, ruby: "2.5", ruby_release: "2.5.1"),
        Distribution.define("focal", "ubuntu", %w[20.04 focal fossa default], debhelper_compat: 12, ruby: "2.7", ruby_release: "2.7.0"),
        Distribution.define("jammy", "ubuntu", %w[22.04 jammy jellyfish default], debhelper_compat: 13, ruby: "3.0", ruby_release: "3.0.2"),
        Distribution.define("noble", "ubuntu", %w[24.04 noble numbat default], debhelper_compat: 13, ruby: "3.2", ruby_release: "3.2.3"),
        Distribution.define("stretch", "debian", %w[9 stretch default], debhelper_compat: 10, ruby: "2.3", ruby_release: "2.3.3"),
        Distribution.define("buster", "debian", %w[10 buster default], debhelper_compat: 12, ruby: "2.5", ruby_release: "2.5.5"),
        Distribution.define("bullseye", "debian", %w[11 bullseye default], debhelper_compat: 13, ruby: "2.7", ruby_release: "2.7.4"),
        Distribution.define("bookworm", "debian", %w[12 bookworm default], debhelper_compat: 13, ruby: "3.1", ruby_release: "3.1.2"),
        Distribution.define("trixie", "debian", %w[13 trixie default], debhelper_compat: 13, ruby: "3.3", ruby_release: "3.3.8")
      ].to_h { |d| [d.codename, d] }.freeze

      # The built-ins named in +list+ ("bionic,buster"; nil: all of them); an
      # unknown name is an InvalidOption.
      def self.builtin(list)
        return BUILTIN unless list

        names = list.split(",").map(&:strip)
        unknown = names - BUILTIN.keys
        raise InvalidOption, "unknown distribution #{unknown.first.inspect} (known: #{BUILTIN.keys.join(', ')})" \
          unless unknown.empty?

        BUILTIN.slice(*names)
      end

      # Built-ins overlaid with a spec's own definitions ({codename =>
      # {"type", "labels", "archive"}}); a built-in keeps what an override leaves out.
      def self.with_overrides(definitions)
        own = (definitions || {}).to_h do |codename, definition|
          known = BUILTIN[codename]
          compat = definition["debhelper_compat"] || known&.debhelper_compat || DEFAULT_DEBHELPER_COMPAT
          [codename, Distribution.define(codename, definition["type"] || known&.type,
                                         definition["labels"] || known&.labels || [], archive: definition["archive"],
                                                                                      debhelper_compat: compat, ruby: known&.ruby,
                                                                                      ruby_release: known&.ruby_release)]
        end
        BUILTIN.merge(own).freeze
      end
    end
  end
end
