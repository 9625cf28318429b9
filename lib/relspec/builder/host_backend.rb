# frozen_string_literal: true

require "fileutils"
require "open3"
require "tmpdir"
require_relative "../error"
require_relative "produced_files"
require_relative "shell_line"

module Relspec
  module Builder
    # Builds on this machine with dpkg-buildpackage, for development and
    # quick tests: the build-dependencies are the packages installed here
    # (relspec installs nothing). Each build unpacks the source into a fresh
    # temporary folder.
    #
    # Build-dependencies that are packages of the release built earlier in
    # the same run are not installed either: their .debs are unpacked
    # (dpkg-deb -x) into a private folder whose /opt is laid over the real
    # /opt (overlayfs, read-only) in a mount namespace of the build alone
    # (`unshare --mount`, which needs root or user namespaces). Only files
    # under /opt are visible that way, which is where Rock releases install.
    # The packages of local repositories (the release's own and its
    # ancestors', e.g. a parent release published on this machine) are made
    # visible the same way. What those packages depend on among them is laid
    # over too (apt would install it: orogen's env.sh sources typelib's), and
    # their shlibs go to the build's debian/shlibs.local: dpkg does not know
    # them as installed, so dpkg-shlibdeps would find a library of theirs
    # (rtt_typelib links typelib's) and no package for it.
    class HostBackend
      NAME = "host"
      # What dpkg-checkbuilddeps prints before the relations it misses.
      UNMET = /Unmet build dependencies: (.*)$/
      # It separates those relations by spaces (not commas): "a (>= 1) b | c".
      PACKAGE = /[^\s(|]+(?:\s*\([^)]*\))?/
      RELATION = /#{PACKAGE}(?:\s*\|\s*#{PACKAGE})*/

      def initialize(tool)
        @tool = tool
      end

      def name
        NAME
      end

      # Nothing to prepare: the machine is the build environment.
      def prepare(_target, log: nil); end

      # Nothing to clean up after a target or a run either.
      def finish_target(_target); end

      def finish; end

      def build(request)
        Dir.mktmpdir("relspec-host-build") do |work|
          tree = File.join(work, "source")
          @tool.run(request.source, ["dpkg-source", "-x", request.dsc, tree], log: request.log)
          available = available_debs(request)
          local = with_dependencies(check_build_dependencies(request, tree, available), available, request.log)
          command = ["dpkg-buildpackage", "-us", "-uc", "-b", "-d"]
          unless local.empty?
            add_shlibs(tree, local, request.log)
            command = overlay(request, work, local) + command
          end
          @tool.run(request.source, command, log: request.log, chdir: tree, name: "dpkg-buildpackage")
          ProducedFiles.collect(work, request.output_dir)
        end
      end

      # The shell lines of a Slurm job that builds +request+ in the folder
      # +work+ (Slurm::JobScript runs them there). The node's installed
      # packages are the build-dependencies (dpkg-buildpackage -d: no check
      # there); +local_debs+ (files or folders of .debs) are laid over /opt.
      def job_steps(request, work)
        debs = request.repositories.flat_map { |repository| repository.pool_debs(request.target) } + request.local_debs
        build = ["dpkg-buildpackage", "-us", "-uc", "-b", "-d"]
        steps = [ShellLine.join(["dpkg-source", "-x", request.dsc, File.join(work, "source")])]
        unless debs.empty?
          root = File.join(work, "local-root")
          steps << ShellLine.join(["mkdir", "-p", File.join(root, "opt")])
          # a folder (the results of a package built earlier in the run) gives all its .debs
          patterns = debs.map { |deb| deb.end_with?(".deb") ? ShellLine.quote(deb) : "#{ShellLine.quote(deb)}/*.deb" }
          steps << "for deb in #{patterns.join(' ')}; do [ ! -f \"$deb\" ] || { dpkg-deb -x \"$deb\" " \
                   "#{ShellLine.quote(root)} && { dpkg-deb -I \"$deb\" shlibs >> source/debian/shlibs.local " \
                   "2>/dev/null || true; }; }; done"
          build = overlay_prefix(root) + build
        end
        steps << "cd source && #{ShellLine.join(build)}"
      end

      # Nothing to prepare on a node either.
      def prepare_steps(_target)
        ["true"]
      end

      private

      # The build-dependencies missing on this machine, less the ones built
      # in this run (returned: their .debs); any other missing one fails the
      # build, named.
      def check_build_dependencies(request, tree, local)
        output, status = Open3.capture2e("dpkg-checkbuilddeps", chdir: tree)
        File.open(request.log, "a") { |file| file.puts("$ dpkg-checkbuilddeps", output) }
        return [] if status.success?

        unmet = output[UNMET, 1] or
          raise BuildError, "#{request.source}: dpkg-checkbuilddeps failed (exit status #{status.exitstatus}), " \
                            "see #{request.log}"
        relations = unmet.scan(RELATION)
        missing = relations.reject { |relation| relation.split(/\s*\|\s*/).any? { |alt| local[alt[/\A[^\s(:]+/]] } }
        unless missing.empty?
          raise BuildError, "#{request.source}: build-dependencies missing on this machine: #{missing.join(', ')} " \
                            "(relspec looked at the packages installed here, as dpkg-checkbuilddeps does; install " \
                            "them, or build with --backend sbuild), see #{request.log}"
        end
        relations.flat_map { |relation| relation.split(/\s*\|\s*/) }
                 .filter_map { |alt| local[alt[/\A[^\s(:]+/]] }.uniq
      end

      # Package name => .deb of what this build may lay over /opt: the local
      # repositories' packages and the ones built earlier in the run.
      def available_debs(request)
        (request.repositories.flat_map { |repository| repository.pool_debs(request.target) } +
         request.local_debs).to_h { |deb| [File.basename(deb).split("_").first, deb] }
      end

      # +debs+ and, through their Depends, every package of +available+ they
      # need, as apt would install them.
      def with_dependencies(debs, available, log)
        found = debs.dup
        found.each do |deb|
          depends = deb_field(deb, "Depends", log)
          names = depends.split(/[,|]/).map { |alt| alt.strip[/\A[^\s(:]+/] }
          found.concat(names.filter_map { |name| available[name] }.reject { |dep| found.include?(dep) }.uniq)
        end
        found
      end

      def deb_field(deb, field, log)
        output, status = Open3.capture2e("dpkg-deb", "-f", deb, field)
        raise BuildError, "cannot read #{field} of #{deb}: #{output.strip}, see #{log}" unless status.success?

        output
      end

      # The shlibs of +debs+ into the build's debian/shlibs.local (after any
      # the package has); a package without a library has none.
      def add_shlibs(tree, debs, log)
        lines = debs.map do |deb|
          output, status = Open3.capture2e("dpkg-deb", "--info", deb, "shlibs")
          status.success? ? output : ""
        end.join
        return if lines.empty?

        File.open(File.join(tree, "debian", "shlibs.local"), "a") { |file| file.write(lines) }
        File.open(log, "a") { |file| file.puts("# shlibs of the packages laid over /opt:", lines) }
      end

      # The command prefix that runs a build with +debs+ visible under /opt.
      def overlay(request, work, debs)
        root = File.join(work, "local-root")
        FileUtils.mkdir_p(File.join(root, "opt"))
        debs.each { |deb| @tool.run(request.source, ["dpkg-deb", "-x", deb, root], log: request.log) }
        overlay_prefix(root)
      end

      def overlay_prefix(root)
        ["unshare", "--mount", "--propagation", "private", "sh", "-c",
         'mount -t overlay relspec-build -o "lowerdir=$0/opt:/opt" /opt && exec "$@"', root]
      end
    end
  end
end
