# frozen_string_literal: true

require "open3"
require "yaml"
require "tmpdir"
require_relative "../error"

module Relspec
  module Mirror
    # The two proofs that a mirror is complete for a target, run on the
    # mirror's own files only.
    #
    # Static: dose-debcheck (Debian's dose-distcheck) over the mirror's
    # Packages index: every package in it is installable from it, with the
    # unsatisfied dependency of each broken one.
    #
    # Dynamic: a clean system made by mmdebstrap (unshare mode) with the
    # mirror as its only source, in a network namespace of its own that has
    # no interface but a down loopback (nothing can be fetched from
    # anywhere else), with every package of the release installed into it
    # by apt at once: installable together, and a machine can be installed
    # from the mirror alone.
    class Proof
      # +name+: static or dynamic; +status+: passed, failed or skipped;
      # +problems+: lines naming what is missing and who needs it.
      Check = Struct.new(:name, :status, :problems, :detail, keyword_init: true) do
        def passed? = status == "passed"
      end

      # apt-get as mmdebstrap runs it for --include (from outside, into the
      # chroot), with "--" before the names: --include puts them after
      # "install" as they are, where one starting with "-" is an apt option.
      # The names come in by the environment, never as shell text; the hook
      # runs before the automount hook unmounts the mirror.
      PACKAGES_VARIABLE = "RELSPEC_MIRROR_PACKAGES"
      INSTALL_HOOK = 'set -f; env APT_CONFIG="$MMDEBSTRAP_APT_CONFIG" apt-get --yes ' \
                     "-oDPkg::Chroot-Directory=\"$1\" install -- $#{PACKAGES_VARIABLE}".freeze

      def initialize(repository)
        @repository = repository
      end

      def static(target)
        index = @repository.index_path(target)
        output, error, status = Open3.capture3("dose-debcheck", "--deb-native-arch=#{target.arch}", "--failures",
                                               "--explain", index)
        report = YAML.safe_load(output)
        unless report.is_a?(Hash) && report.key?("broken-packages")
          raise ToolError, "dose-debcheck failed on #{index}: #{(error + output).strip.lines.last(3).join.strip} " \
                           "(apt-get install dose-distcheck)"
        end

        problems = Array(report["report"]).flat_map { |entry| broken(entry) }
        Check.new(name: "static", status: status.success? && problems.empty? ? "passed" : "failed",
                  problems: problems, detail: "#{report['total-packages']} packages, " \
                                              "#{report['broken-packages']} broken (dose-debcheck)").freeze
      rescue SystemCallError => e
        raise ToolError, "cannot run dose-debcheck: #{e.message} (apt-get install dose-distcheck)"
      end

      # +names+: the release's packages. +arch_runs+: false when this
      # machine cannot run the target's binaries (no emulation): skipped.
      def dynamic(target, names, sign_key: nil, arch_runs: true)
        unless arch_runs
          return Check.new(name: "dynamic", status: "skipped", problems: [],
                           detail: "this machine cannot run #{target.arch} programs (set up qemu-user-static and " \
                                   "binfmt as bin/emulation-smoke does)").freeze
        end

        output, status = install(target, names, sign_key)
        problems = status.success? ? [] : apt_problems(output)
        Check.new(name: "dynamic", status: status.success? ? "passed" : "failed", problems: problems,
                  detail: "mmdebstrap from the mirror alone, no network, #{names.size} release packages installed " \
                          "with apt").freeze
      end

      private

      def broken(entry)
        Array(entry["reasons"]).filter_map do |reason|
          missing = reason["missing"]
          next "#{entry['package']} #{entry['version']}: conflicts (#{reason.keys.join(', ')})" unless missing

          "#{missing.dig('pkg', 'unsat-dependency')} is missing (needed by #{missing.dig('pkg', 'package')} " \
            "#{missing.dig('pkg', 'version')}, for #{entry['package']})"
        end
      end

      # mmdebstrap in unshare mode reads the mirror as the namespace's
      # root (a subordinate uid): the mirror must be readable by others.
      def install(target, names, sign_key)
        Open3.capture2e({ PACKAGES_VARIABLE => names.join(" ") }, *install_command(target, sign_key))
      rescue SystemCallError => e
        raise ToolError, "cannot run mmdebstrap: #{e.message} (apt-get install mmdebstrap uidmap)"
      end

      def install_command(target, sign_key)
        source = "deb [#{sign_key ? "signed-by=#{sign_key}" : 'trusted=yes'}] file://#{@repository.dir} " \
                 "#{target.codename} main"
        ["unshare", "--net", "--", "mmdebstrap", "--mode=unshare", "--variant=apt", "--quiet",
         "--architectures=#{target.arch}", "--format=null", "--customize-hook=#{INSTALL_HOOK}",
         "--hook-dir=/usr/share/mmdebstrap/hooks/file-mirror-automount",
         "--dpkgopt=force-unsafe-io", "--aptopt=Acquire::Languages \"none\"", target.codename, "/dev/null", source]
      end

      # What apt said it could not find or install, else the last lines.
      def apt_problems(output)
        lines = output.lines.map(&:strip)
        found = lines.grep(/(Depends:|Unable to locate package|has no installation candidate|but it is not installable|E: )/)
        (found.empty? ? lines.last(5) : found.first(20)).uniq
      end
    end
  end
end
