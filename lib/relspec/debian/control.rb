# frozen_string_literal: true

require_relative "template"
require_relative "debhelper"
require_relative "control_relations"

module Relspec
  module Debian
    # debian/control and the lintian overrides of one package, from its
    # BuildInput: what it is called, what it needs to build and to run, and
    # whether it is architecture-dependent.
    class Control
      SECTIONS = { "ruby" => "ruby", "gem" => "ruby", "import" => "misc", "archive" => "misc",
                   "meta" => "metapackages" }.freeze
      ARCH_INDEPENDENT = %w[ruby import archive meta].freeze

      Context = Struct.new(:source, :section, :maintainer, :build_depends, :depends, :homepage, :architecture,
                           :synopsis, :long_description, keyword_init: true)
      METHODS = Template.compile(Context, %w[control.erb])

      def initialize(input)
        @in = input
      end

      def control
        Template.render(Context, METHODS, "control.erb",
                        source: @in.deb_name, section: SECTIONS.fetch(build_type, "devel"), maintainer: @in.maintainer,
                        build_depends: build_depends, depends: depends, homepage: homepage, architecture: architecture,
                        synopsis: synopsis, long_description: long_description)
      end

      # A gem or a Ruby package is architecture-dependent only when it
      # compiles an extension.
      def architecture
        return @in.gem.native? ? "any" : "all" if build_type == "gem"
        return "any" if @in.extension_task

        ARCH_INDEPENDENT.include?(build_type) ? "all" : "any"
      end

      # Packages of a release live under /opt by design (docs/compile.md): lintian
      # names /opt/rock/, /opt/rock/<release>/ and every path of the prefix.
      # Their libraries are not on ld.so's path, so Rock's CMake gives
      # programs a RUNPATH to the release's prefixes (the only way they run
      # without env.sh): custom-library-search-path is that, by design.
      def lintian_overrides
        source = @in.deb_name
        folders = @in.install_dir.delete_prefix("/").split("/")
        parents = folders.each_index.map { |index| folders[0..index].join("/") }
        lines = ["# packages of a release live in /opt by design"]
        lines += parents[1..-2].to_a.map { |dir| "#{source}: dir-or-file-in-opt [#{dir}/]" }
        lines << "#{source}: dir-or-file-in-opt [#{parents.last}/*]"
        if architecture == "any"
          lines += ["# libraries of the release are found through RUNPATH into its prefixes under /opt",
                    "#{source}: custom-library-search-path"]
        end
        "#{lines.join("\n")}\n"
      end

      private

      def build_type
        @in.package.build_type
      end

      def own_relations
        @in.dependencies.map { |dep| "#{dep.deb_name} (>= #{dep.version})" }
      end

      # The OS part: apt names and distribution gems (already ruby-<gem>).
      def os_relations
        ControlRelations.os_relations(@in.apt, @in.gems)
      end

      def build_depends
        compat = @in.debhelper_compat
        ControlRelations.build_depends(build_type, own_relations,
                                       os_relations + Debhelper.autoreconf(build_type, compat) +
                                         (@in.extension_task ? ["ruby-dev"] : []),
                                       debhelper: Debhelper.relation(compat), closure: @in.closure_tools)
      end

      def depends
        ControlRelations.depends(build_type, architecture, own_relations, os_relations,
                                 ships_headers: @in.gem&.ships_headers? || false)
      end

      def synopsis
        package = @in.package
        text = [package.summary, package.description, package.name].find { |candidate| candidate && !candidate.strip.empty? }
        text = text.lines.first.to_s.strip.delete_suffix(".")
        text = "#{package.name} of release #{@in.release}" if text.empty?
        text.length > 78 ? "#{text[0, 75]}..." : text
      end

      def homepage
        url = @in.gem ? @in.gem.spec.homepage.to_s : @in.package.vcs.url.to_s
        return nil if build_type == "meta"

        url.match?(%r{\Ahttps?://}) ? url.delete_suffix(".git") : nil
      end

      # Description paragraphs as debian/control wants them: one leading
      # space, "." for empty lines.
      # manifest.xml indents its text like the XML around it: each line is
      # taken without its indentation (a Debian description line starting
      # with two spaces would be shown verbatim), runs of empty lines become
      # one, and a first paragraph that only repeats the synopsis is left out.
      def long_description
        text = @in.package.description || synopsis
        lines = text.strip.lines.map(&:strip).chunk_while { |a, b| a.empty? && b.empty? }.map(&:first)
        lines = lines.drop(1).drop_while(&:empty?) if lines.first&.delete_suffix(".") == synopsis && lines.size > 1
        lines += ["", "Built from #{@in.package.name} for release #{@in.release}."]
        lines.map { |line| line.empty? ? " ." : " #{line}" }.join("\n")
      end
    end
  end
end
