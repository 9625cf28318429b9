# frozen_string_literal: true

require "thor"
require_relative "checked_options"
require_relative "strict_commands"
require_relative "../version"
require_relative "catalog_commands"
require_relative "osdeps_commands"
require_relative "help"

module Relspec
  module CLI
    # The command line (README.md lists the commands). Each command is a small class; this file
    # only declares options and hands them over. Command classes are required
    # when their command runs, so that each command loads only what it needs.
    class Main < Thor
      include CheckedOptions
      include StrictCommands

      package_name "relspec"

      def self.exit_on_failure?
        true
      end

      def self.command_group
        "relspec"
      end

      # Thor's errors come out as relspec's (StrictCommands).
      def self.start(given_args = ARGV, config = {})
        StrictCommands.translated { super(given_args, config.merge(debug: true)) }
      end

      DISCARD_LOCK = "Start over when releases/<release>/lock.yml cannot be read (its build history is lost)"

      class_option :debug, type: :boolean, default: false, desc: "Show backtraces of internal errors"
      class_option :quiet, type: :boolean, default: false, desc: "No progress output"

      map %w[--version -v] => :version

      desc "version", "Print relspec's version"
      def version
        puts "relspec #{VERSION}"
      end

      desc "validate [SPEC...]", "Check release specs and their ancestors (default: every spec in specs/)"
      long_desc Help::VALIDATE
      option :format, enum: %w[text json], default: "text", desc: "Output format"
      def validate(*paths)
        require_relative "validate_command"
        finish ValidateCommand.new(paths: paths, format: options[:format], out: $stdout, err: $stderr).call
      end

      desc "show SPEC", "Print the effective spec of a release after inheritance"
      long_desc Help::SHOW
      option :origins, type: :boolean, default: false, desc: "Annotate each value with where it was written"
      option :format, enum: %w[yaml json], default: "yaml", desc: "Output format"
      def show(path)
        require_relative "show_command"
        finish ShowCommand.new(path: path, format: options[:format], origins: options[:origins],
                               out: $stdout, err: $stderr).call
      end

      desc "plan SPEC | --check [SPEC...]", "Decide per target what the release inherits, builds or has published, and why"
      long_desc Help::PLAN
      option :write, type: :boolean, default: false, desc: "Write releases/<release>/lock.yml"
      option :format, enum: %w[text json markdown], default: "text", desc: "Output format"
      option :target, type: :string, desc: "Only this target (codename/arch)"
      option :timeout, type: :numeric, default: 10, desc: "HTTP timeout in seconds"
      option :discard_lock, type: :boolean, default: false, desc: DISCARD_LOCK
      option :check, type: :boolean, default: false,
                     desc: "Exit 1 when a committed lock is out of date with its spec, workspace or ancestors (default: every spec in specs/)"
      def plan(*paths)
        if options[:check]
          require_relative "plan_check_command"
          return finish(PlanCheckCommand.new(paths: paths, timeout: options[:timeout], out: $stdout).call)
        end
        raise Error, "relspec plan needs one SPEC (or --check [SPEC...])" unless paths.size == 1

        path = paths.first
        require_relative "plan_command"
        finish PlanCommand.new(path: path, format: options[:format], write: options[:write], target: options[:target],
                               timeout: options[:timeout], out: $stdout, err: $stderr,
                               discard_lock: options[:discard_lock]).call
      end

      desc "compile SPEC", "Emit the Debian source packages the release must build, plan.yml, lock and osdeps"
      long_desc Help::COMPILE
      option :out, type: :string, default: "build", desc: "Where the source packages go"
      option :jobs, type: :numeric, default: 2, desc: "Packages emitted in parallel"
      option :timeout, type: :numeric, default: 10, desc: "HTTP timeout in seconds"
      option :discard_lock, type: :boolean, default: false, desc: DISCARD_LOCK
      option :check, type: :boolean, default: true, desc: "Refuse a release with missing OS dependencies (--no-check: skip)"
      option :launchpad_url, type: :string, default: "https://api.launchpad.net/1.0", desc: "Whose cached answers to use"
      def compile(path)
        require_relative "compile_command"
        finish CompileCommand.new(path: path, out: options[:out], jobs: options[:jobs], timeout: options[:timeout],
                                  out_io: $stdout, progress_io: options[:quiet] ? nil : $stderr,
                                  discard_lock: options[:discard_lock],
                                  check: options[:check] && { launchpad_base: options[:launchpad_url] }).call
      end

      desc "publish SPEC", "Put what relspec build built into the release's reprepro repository"
      long_desc Help::PUBLISH
      option :out, type: :string, default: "build", desc: "Where relspec compile and build wrote"
      option :target, type: :string, desc: "Only this target (codename/arch)"
      option :timeout, type: :numeric, default: 10, desc: "HTTP timeout in seconds"
      def publish(path)
        require_relative "publish_command"
        finish PublishCommand.new(path: path, out: options[:out], target: options[:target], timeout: options[:timeout],
                                  out_io: $stdout, err_io: $stderr).call
      end

      desc "report SPEC", "Write the release's status page (<out>/<release>/report/index.html; docs/report.md)"
      option :out, type: :string, default: "build", desc: "Where relspec compile and build wrote"
      option :format, enum: %w[html json], default: "html", desc: "Output format"
      def report(path)
        require_relative "report_command"
        finish ReportCommand.new(path: path, out: options[:out], format: options[:format], out_io: $stdout).call
      end

      desc "abi SPEC", "ABI verdict of each library the release builds, against the ancestors' dumps (docs/abi.md)"
      option :out, type: :string, default: "build", desc: "Where relspec compile and build wrote"
      option :target, type: :string, desc: "Only this target (codename/arch)"
      option :against, type: :string, desc: "Compare with this release (an ancestor, or the release itself)"
      option :format, enum: %w[text markdown json], default: "text", desc: "Output format"
      option :fail_on, enum: %w[changed incompatible], desc: "Exit 1 when a library's verdict is this or worse"
      def abi(path)
        require_relative "abi_command"
        finish AbiCommand.new(path: path, out: options[:out], target: options[:target], against: options[:against],
                              format: options[:format], fail_on: options[:fail_on], out_io: $stdout).call
      end

      desc "build SPEC", "Build the source packages compile wrote, in dependency order (sbuild or this host)"
      long_desc Help::BUILD
      option :out, type: :string, default: "build", desc: "Where compile wrote the source packages"
      option :backend, enum: %w[sbuild host], default: "sbuild", desc: "sbuild (clean chroot) or host (this machine)"
      option :jobs, type: :numeric, default: 1, desc: "Packages built at once"
      option :target, type: :string, repeatable: true, desc: "Only this target (codename/arch); repeatable"
      option :keep_going, type: :boolean, default: false, desc: "Build what does not depend on a failed package"
      option :rebuild, type: :boolean, default: false, desc: "Rebuild packages an earlier run built"
      option :rebuild_dependents, type: :boolean, default: false, desc: "Build every early cutoff candidate (docs/abi.md)"
      option :prepare, type: :boolean, default: false, desc: "Only make the chroot tarballs (sbuild)"
      option :format, enum: %w[text json], default: "text", desc: "Output format"
      option :engine, enum: %w[local slurm], default: "local",
                      desc: "local (--jobs at once here) or slurm (jobs on a Slurm cluster; docs/scale-out.md)"
      option :slurm, type: :string, repeatable: true,
                     desc: "A cluster setting KEY=VALUE (partition, account, time_limit, memory, cpus_per_build, " \
                           "shared_folder, poll_interval, features.ARCH); repeatable"
      def build(path)
        require_relative "build_command"
        require_relative "build_progress"
        require_relative "build_progress_lines"
        finish BuildCommand.new(path: path, **%i[out backend jobs keep_going rebuild prepare format engine rebuild_dependents]
                                                .to_h { |key| [key, options[key]] },
                                targets: options[:target], out_io: $stdout, progress_io: options[:quiet] ? nil : $stderr,
                                slurm: options[:slurm] || [], err_io: $stderr).call
      end

      desc "mirror SPEC --out DIR | mirror verify DIR",
           "A field mirror of a release and all it needs, proven complete offline (docs/mirror.md)"
      option :out, type: :string, desc: "The mirror's folder"
      option :target, type: :string, repeatable: true, desc: "Only this target (codename/arch); repeatable"
      option :format, enum: %w[text json], default: "text", desc: "Output format"
      option :install, type: :boolean, default: true, desc: "Run the dynamic proof (install from the mirror)"
      option :timeout, type: :numeric, default: 10, desc: "HTTP timeout in seconds"
      def mirror(*args)
        require_relative "mirror_command"
        finish MirrorCommand.new(args: args, options: options, out_io: $stdout, err_io: $stderr).call
      end

      desc "check SPEC", "Check that the OS dependencies of the release exist on every target"
      long_desc Help::CHECK
      option :target, type: :string, desc: "Only this target (codename/arch)"
      option :source, enum: %w[auto apt launchpad], default: "auto", desc: "Where availability is read"
      option :format, enum: %w[text json markdown], default: "text", desc: "Output format"
      option :timeout, type: :numeric, default: 10, desc: "HTTP timeout in seconds"
      option :launchpad_url, type: :string, default: "https://api.launchpad.net/1.0", desc: "Launchpad web service root"
      option :concurrency, type: :numeric, default: 4, desc: "Launchpad requests in flight at once"
      def check(path)
        require_relative "check_command"
        finish CheckCommand.new(path: path, format: options[:format], target: options[:target], source: options[:source],
                                timeout: options[:timeout], launchpad_url: options[:launchpad_url],
                                concurrency: options[:concurrency], out: $stdout).call
      end

      desc "why SPEC PACKAGE", "Explain one package's decision, with its full cause chain"
      option :target, type: :string, desc: "Only this target (codename/arch)"
      option :timeout, type: :numeric, default: 10, desc: "HTTP timeout in seconds"
      def why(path, package)
        require_relative "why_command"
        finish WhyCommand.new(path: path, package: package, target: options[:target], timeout: options[:timeout],
                              out: $stdout).call
      end

      desc "diff OLD NEW | --base REF [SPEC...]", "What a change does to each release: per target, what is added, removed, rebuilt, and why"
      long_desc Help::DIFF
      option :base, type: :string, desc: "Compare the working tree against this git ref (e.g. origin/main)"
      option :format, enum: %w[text markdown json], default: "text", desc: "Output format"
      option :exit_code, type: :boolean, default: false, desc: "Exit 1 when something differs, 2 on an error"
      option :fail_on_rebuilds, type: :numeric, desc: "Exit 1 when more than this many packages are rebuilt"
      option :color, type: :boolean, desc: "Colour the text format (default: when writing to a terminal)"
      option :abi_out, type: :string, desc: "With the builds there, show the rebuilt libraries' ABI verdicts (docs/abi.md)"
      option :timeout, type: :numeric, default: 10, desc: "HTTP timeout in seconds (specs are planned)"
      def diff(*paths)
        require_relative "diff_command"
        require_relative "friendly_errors"
        status = 0
        failed = FriendlyErrors.wrap(stderr: $stderr, debug: options[:debug]) do
          status = DiffCommand.new(paths: paths, base: options[:base], format: options[:format],
                                   exit_code: options[:exit_code], fail_on_rebuilds: options[:fail_on_rebuilds]&.to_i,
                                   timeout: options[:timeout], out: $stdout, err: $stderr,
                                   color: options.fetch(:color) { $stdout.tty? }, abi_out: options[:abi_out]).call
        end
        # With --exit-code, 1 means "differences": an error must say 2.
        failed = DIFF_ERROR if failed.nonzero? && options[:exit_code]
        finish(failed.zero? ? status : failed)
      end

      # `diff --exit-code` status of an error (as `diff` and `git diff`).
      DIFF_ERROR = 2

      desc "catalog SUBCOMMAND", "The package database of a workspace (export, show)"
      subcommand "catalog", CatalogCommands

      desc "osdeps SUBCOMMAND", "osdeps files for autoproj (render SPEC, index, select, package-set); `osdeps SPEC` renders"
      subcommand "osdeps", OsdepsCommands

      # Options of every command that people also write before the command
      # (`relspec --debug compile SPEC`); Thor only reads them after it.
      GLOBAL_FLAGS = %w[--debug --no-debug --quiet --no-quiet].freeze

      def self.normalize(argv)
        leading = argv.take_while { |arg| GLOBAL_FLAGS.include?(arg) }
        argv = argv.drop(leading.size) + leading unless leading.empty? || argv.size == leading.size
        return argv unless argv[0] == "osdeps" && argv[1] && spec_path?(argv[1])

        [argv[0], "render", *argv[1..]]
      end

      # `relspec osdeps SPEC` is `relspec osdeps render SPEC`; any other word
      # is a subcommand, refused with a hint when unknown (never a spec path).
      def self.spec_path?(word)
        word.match?(/\.ya?ml\z/) || word.include?("/") || File.file?(word)
      end

      private

      def finish(status)
        exit(status) unless status.zero?
      end
    end
  end
end
