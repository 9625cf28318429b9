# frozen_string_literal: true

require "erb"
require "digest"
require_relative "naming"
require_relative "control_relations"
require_relative "license_name"
require_relative "build_input"
require_relative "environment_file"
require_relative "../osdeps/trust"
require_relative "../yaml/writer"
require_relative "../catalog/prefix_markers"
require_relative "../catalog/cmake_defines"
require_relative "../catalog/ruby_extension"

module Relspec
  module Debian
    # The debian/ folder of one package built in a release, from ERB
    # templates per build type (3.0 (quilt); the debhelper compat level of
    # the target distribution, whose features the templates keep to).
    #
    # Input: a BuildInput (the catalog Package, its Debian name and version,
    # the target, the release's settings, its dependencies as decided on the
    # target and its OS dependencies resolved for the codename).
    class DebianDir
      TEMPLATES = File.join(__dir__, "templates")
      SECTIONS = { "ruby" => "ruby", "gem" => "ruby", "import" => "misc", "archive" => "misc",
                   "meta" => "metapackages" }.freeze
      ARCH_INDEPENDENT = %w[ruby import archive meta].freeze
      DH_OPTIONS = { "cmake" => " --buildsystem=cmake", "orogen" => " --buildsystem=cmake",
                     "autotools" => " --buildsystem=autoconf" }.freeze

      # Stands for the version in the debian/ whose digest decides the
      # revision (the digest must not depend on what it decides).
      VERSION_PLACEHOLDER = "@RELSPEC_VERSION@"

      # +input+: BuildInput; +version+: the PackageVersion, or nil for the
      # digest's rendering.
      def self.render(input, version:)
        new(input).render(version)
      end

      def initialize(input)
        @in = input
      end

      # {relative path => [content, mode]}
      def render(version)
        files = {
          "control" => template("control.erb"),
          "changelog" => template("changelog.erb", version: (version || VERSION_PLACEHOLDER).to_s),
          "copyright" => template("copyright.erb"),
          "rules" => template("rules.erb", body: template("rules_#{rules_kind}.erb")),
          "source/format" => "3.0 (quilt)\n",
          "env.sh" => template("env.sh.erb"),
          "env.yml" => EnvironmentFile.render(environment_variables, more: package_environment),
          "relspec.yml" => Yaml::Writer.dump(metadata),
          "#{source}.lintian-overrides" => lintian_overrides
        }
        # debhelper-compat in Build-Depends needs debhelper 11.1.4; older ones read debian/compat
        files["compat"] = "#{compat}\n" if compat < BUILD_DEPENDS_COMPAT
        files.to_h { |path, content| [path, [content, path == "rules" ? 0o755 : 0o644]] }
      end

      # What debian/ is made of, independent of the revision: when it changes
      # for the same upstream version, the revision goes up.
      def self.digest(files)
        Digest::SHA256.hexdigest(files.sort.map { |path, (content, mode)| "#{path}\0#{mode}\0#{content}" }.join("\0"))
      end

      private

      # What the templates see: the variables below, plus +version+
      # (changelog) and +body+ (rules).
      Context = Struct.new(:source, :section, :maintainer, :build_depends, :depends, :homepage, :architecture,
                           :synopsis, :long_description, :codename, :release, :package_name, :vcs_url, :vcs_ref,
                           :commit, :date, :copyright_holders, :license, :license_name, :common_license, :public_source, :build_type, :install_dir, :dh_options,
                           :canonical, :dependency_dirs, :gem_dir, :cmake_options, :orogen_command, :guard, :gem_file, :version,
                           :body, :ruby_lib_dirs, :package_environment, :extension_task, :closure_environment, keyword_init: true)

      # Each template becomes a method of Context, compiled once: evaluating
      # ERB source on every render (result_with_hash) cost a no-op compile of
      # 400 packages 0.4 s.
      METHODS = Dir.glob("*.erb", base: TEMPLATES).sort.to_h do |name|
        method = "render_#{name.delete_suffix('.erb').tr('.', '_')}"
        ERB.new(File.read(File.join(TEMPLATES, name)), trim_mode: "-").def_method(Context, "#{method}()", name)
        [name, method.to_sym]
      end.freeze

      def template(name, **locals)
        context = Context.new(**(@variables ||= variables), **locals)
        context.public_send(METHODS.fetch(name))
      end

      def variables
        package = @in.package
        {
          source: source, section: SECTIONS.fetch(package.build_type, "devel"), maintainer: @in.maintainer,
          build_depends: build_depends, depends: depends, homepage: homepage, architecture: architecture,
          synopsis: synopsis, long_description: long_description, codename: @in.codename,
          release: @in.release, package_name: package.name, vcs_url: shown_url(package.vcs.url.to_s),
          vcs_ref: vcs_ref(package.vcs), commit: package.vcs.commit.to_s, date: changelog_date,
          copyright_holders: copyright_holders, license: license_text, license_name: LicenseName.of(license_text),
          common_license: LicenseName.common_license_file(LicenseName.of(license_text)),
          public_source: public_url(package.vcs.url.to_s),
          build_type: package.build_type, install_dir: install_dir, dh_options: dh_options(package.build_type),
          canonical: Naming.canonical(package.name), dependency_dirs: dependency_dirs, closure_environment: @in.closure_environment.select { |name| BuildInput.variable?(name) },
          gem_dir: GEM_DIR, cmake_options: cmake_options, orogen_command: orogen_command,
          guard: "RELSPEC_ENV_#{source.gsub(/[^A-Za-z0-9]/, '_')}", gem_file: gem_file, ruby_lib_dirs: ruby_lib_dirs,
          package_environment: package_environment, extension_task: Catalog::RubyExtension.checked(package)
        }
      end

      BUILD_DEPENDS_COMPAT = 11

      # Where gems install below a package's prefix (GEM_PATH entry). Not
      # lib/ruby/gems: Rock's FindGem.cmake takes every file whose path has
      # "<gem name>…/lib/" as a library of the gem, and a prefix named
      # …-ruby-<gem> followed by /lib/ made it link every sample .so of rice.
      GEM_DIR = "gems"

      def compat
        @in.debhelper_compat
      end

      def debhelper
        compat < BUILD_DEPENDS_COMPAT ? "debhelper (>= #{compat})" : "debhelper-compat (= #{compat})"
      end

      # What Rock's autoproj configuration gives CMake for a package: its
      # build type, tests off (base/cmake's ROCK_TEST_ENABLED); then the
      # package set's defines (pkg.define, Autobuild::CMake.define), which
      # win; then the prefix, which the release decides. Each option is one
      # shell word; "$" is doubled for make. A define naming another
      # package's prefix gets the prefix the release gives that package; one
      # naming a package the release does not have on the target is left
      # out, as if the package set had not seen the package. One naming the
      # workspace's Ruby gets the target's.
      ROCK_CMAKE_DEFINES = { "CMAKE_BUILD_TYPE" => "Release", "ROCK_TEST_ENABLED" => "OFF" }.freeze

      def cmake_options
        defines = ROCK_CMAKE_DEFINES.merge(released_defines)
                                    .merge("CMAKE_INSTALL_PREFIX" => "$(PREFIX)", "CMAKE_INSTALL_LIBDIR" => "lib")
        defines.map do |name, value|
          option = "-D#{name}=#{value}"
          value == "$(PREFIX)" ? option : shell_word(option.gsub("$", "$$"))
        end.join(" ")
      end

      def released_defines
        @in.package.defines.filter_map do |name, value|
          names = value.scan(Catalog::PrefixMarkers::REFERENCE).flatten
          next unless names.all? { |package| @in.prefixes.key?(package) }

          [name, value.gsub(Catalog::PrefixMarkers::REFERENCE) { @in.prefixes.fetch(Regexp.last_match(1)) }.gsub(Catalog::CmakeDefines::RUBY) { @in.ruby_executable }]
        end.to_h
      end

      # The generator's words as autoproj gives them (Catalog::OrogenArguments),
      # quoted as cmake_options are. A package read without them (a snapshot
      # of an older relspec) gets autobuild's defaults; one whose .orogen file
      # was not known when it was read, the one in its source.
      DEFAULT_OROGEN_ARGUMENTS = %w[--corba --transports=corba,mqueue,typelib --type-export-policy=used].freeze

      def orogen_command
        words = @in.package.orogen_arguments
        words = DEFAULT_OROGEN_ARGUMENTS if words.empty?
        line = ["orogen", *words.map { |word| shell_word(word.gsub("$", "$$")) }]
        line << "$(wildcard *.orogen)" unless words.last.end_with?(".orogen")
        line.join(" ")
      end

      # One word of a shell line in debian/rules ("$" already doubled for
      # make): a "$" is quoted too, or the shell would expand what make leaves.
      def shell_word(word)
        word.match?(%r{\A[-\w=./:,+]*\z}) ? word : "'#{word.gsub("'", "'\\\\''")}'"
      end

      def source
        @in.deb_name
      end

      # Prefixes of the dependencies built by Rock releases (the
      # distribution's own packages live in the system).
      def dependency_dirs
        @in.dependencies.filter_map(&:install_dir)
      end

      def gem_file
        gem = @in.gem
        gem && "#{gem.name}-#{gem.version}.gem"
      end

      def install_dir
        @in.install_dir
      end

      # What env.sh puts on RUBYLIB. RubyGems activates the highest version
      # of a gem on GEM_PATH wherever it is (this machine has facets 4.0.0 as
      # autoproj's dependency), and activating it for one file rules out the
      # release's version for the next: only RUBYLIB makes the release's
      # version win. A gem of the release: its require paths (facets 3.1.0
      # has lib/core and lib/standard); other packages: <prefix>/lib (a Ruby
      # package's gem links it to its lib/), and for a compiled one also the
      # target Ruby's folders below the prefix, where CMake projects put
      # their bindings (typelib); autoproj adds them for a source-built
      # package when they exist (Autobuild::Environment#add_prefix).
      def ruby_lib_dirs
        gem = @in.gem
        unless gem && @in.package.build_type == "gem"
          compiled = DH_OPTIONS.key?(@in.package.build_type) ? @in.ruby_dirs : []
          return ["lib", *compiled].map { |dir| "#{install_dir}/#{dir}" }
        end

        full_name = gem_file.delete_suffix(".gem")
        gem.spec.require_paths.map { |path| "#{install_dir}/#{GEM_DIR}/gems/#{full_name}/#{path}" }
      end

      def rules_kind
        kind = @in.package.build_type
        kind == "archive" ? "import" : kind
      end

      # A gem or a Ruby package is architecture-dependent only when it
      # compiles an extension.
      def architecture
        return @in.gem.native? ? "any" : "all" if @in.package.build_type == "gem"
        return "any" if @in.package.extension_task

        ARCH_INDEPENDENT.include?(@in.package.build_type) ? "all" : "any"
      end

      def own_relations
        @in.dependencies.map { |dep| "#{dep.deb_name} (>= #{dep.version})" }
      end

      # The OS part: apt names and distribution gems (already ruby-<gem>).
      def os_relations
        ControlRelations.os_relations(@in.apt, @in.gems)
      end

      def build_depends
        ControlRelations.build_depends(@in.package.build_type, own_relations,
                                       os_relations + autoreconf + (@in.package.extension_task ? ["ruby-dev"] : []),
                                       debhelper: debhelper, closure: @in.closure_tools)
      end

      # debhelper runs dh_autoreconf by itself from compat 10 on; before
      # (xenial's 9) it is an add-on of its own package.
      AUTORECONF_BY_DEFAULT = 10

      def old_autotools?
        @in.package.build_type == "autotools" && compat < AUTORECONF_BY_DEFAULT
      end

      def autoreconf
        old_autotools? ? ["dh-autoreconf"] : []
      end

      def dh_options(build_type)
        DH_OPTIONS.fetch(build_type, "") + (old_autotools? ? " --with autoreconf" : "")
      end

      def meta?
        @in.package.build_type == "meta"
      end

      def depends
        ControlRelations.depends(@in.package.build_type, architecture, own_relations, os_relations,
                                 ships_headers: @in.gem&.ships_headers? || false)
      end

      def homepage
        url = @in.gem ? @in.gem.spec.homepage.to_s : @in.package.vcs.url.to_s
        return nil if meta?

        url.match?(%r{\Ahttps?://}) ? url.delete_suffix(".git") : nil
      end

      def synopsis
        package = @in.package
        text = [package.summary, package.description, package.name].find { |candidate| candidate && !candidate.strip.empty? }
        text = text.lines.first.to_s.strip.delete_suffix(".")
        text = "#{@in.package.name} of release #{@in.release}" if text.empty?
        text.length > 78 ? "#{text[0, 75]}..." : text
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

      # The upstream holders (manifest.xml's <copyright>, authors or
      # maintainers; a gem's authors), never the release's maintainer.
      def copyright_holders
        package = @in.package
        holders = package.copyright.empty? ? package.maintainer.to_s.split(", ") : package.copyright
        holders.empty? ? ["the authors of #{package.name}"] : holders
      end

      def license_text
        text = @in.package.license.to_s.strip.gsub(/\s+/, " ")
        text.empty? ? "unknown" : text
      end

      # A repository inside the workspace ($AUTOPROJ_ROOT/…, a folder of
      # the maintainer's machine) is no public source: it is named relative
      # to the workspace, and debian/copyright leaves Source: out.
      WORKSPACE_URL = %r{\A\$AUTOPROJ_ROOT/}

      def shown_url(url)
        url.match?(WORKSPACE_URL) ? "the autoproj workspace's #{url.sub(WORKSPACE_URL, '')}" : url
      end

      def public_url(url)
        url.match?(%r{\A(https?|git|ssh)://|\A[\w.-]+@[\w.-]+:}) ? url : nil
      end

      # Packages of a release live under /opt by design (docs/compile.md): lintian
      # names /opt/rock/, /opt/rock/<release>/ and every path of the prefix.
      # Their libraries are not on ld.so's path, so Rock's CMake gives
      # programs a RUNPATH to the release's prefixes (the only way they run
      # without env.sh): custom-library-search-path is that, by design.
      def lintian_overrides
        parents = install_dir.delete_prefix("/").split("/").each_index.map do |index|
          install_dir.delete_prefix("/").split("/")[0..index].join("/")
        end
        lines = ["# packages of a release live in /opt by design"]
        lines += parents[1..-2].to_a.map { |dir| "#{source}: dir-or-file-in-opt [#{dir}/]" }
        lines << "#{source}: dir-or-file-in-opt [#{parents.last}/*]"
        if architecture == "any"
          lines += ["# libraries of the release are found through RUNPATH into its prefixes under /opt",
                    "#{source}: custom-library-search-path"]
        end
        "#{lines.join("\n")}\n"
      end

      def vcs_ref(vcs)
        if vcs.tag then "tag #{vcs.tag}, "
        elsif vcs.branch then "branch #{vcs.branch}, "
        else ""
        end
      end

      # RFC 2822 date of the commit (never the time of the run).
      def changelog_date
        time = @in.package.commit_time
        Time.utc(*time.scan(/\d+/).map(&:to_i)).strftime("%a, %d %b %Y %H:%M:%S +0000")
      end

      # The package set's own settings of the package (Catalog::Package#environment)
      # for this prefix: [[type, name, values]]. Only what relspec's package
      # set accepts gets through (Osdeps::Trust: a documented variable, a
      # path below the release's prefix or one plain word): a variable it
      # refuses would make it refuse the whole release, a path into the
      # maintainer's workspace ($AUTOPROJ_ROOT) means nothing on a user's
      # machine, and shell syntax would be code in env.sh.
      def package_environment
        @in.package.environment.filter_map do |op|
          values = op.fetch("values").map { |value| value.gsub("$PREFIX", install_dir) }
          entry = { type: op.fetch("type").to_sym, values: values }
          next if values.any? { |value| value.match?(/["$`\\\n]/) }
          next if Osdeps::Trust.environment(op.fetch("name"), entry, prefix: File.dirname(install_dir))

          [op.fetch("type"), op.fetch("name"), values]
        end
      end

      # What the package adds to the environment: one prefix, no dependency
      # (autoproj loads the env.yml of every active package; env.sh, for a
      # plain shell, sources its dependencies itself).
      def environment_variables
        dir = install_dir
        { "PATH" => ["#{dir}/bin"], "LD_LIBRARY_PATH" => ["#{dir}/lib"],
          "PKG_CONFIG_PATH" => ["#{dir}/lib/pkgconfig", "#{dir}/share/pkgconfig"], "CMAKE_PREFIX_PATH" => [dir],
          "RUBYLIB" => ruby_lib_dirs, "GEM_PATH" => ["#{dir}/#{GEM_DIR}"] }
      end

      # relspec's own record of the package (relspec.yml in the prefix): what
      # built it and the prefixes of its dependencies.
      def metadata
        { "package" => @in.package.name, "release" => @in.release, "prefix" => install_dir,
          "dependencies" => dependency_dirs }
      end
    end
  end
end
