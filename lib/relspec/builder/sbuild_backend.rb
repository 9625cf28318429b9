# frozen_string_literal: true

require "etc"
require "fileutils"
require "tmpdir"
require_relative "apt_cache"
require_relative "ccache"
require_relative "chroot"
require_relative "chroot_layers"
require_relative "dependency_layers"
require_relative "../error"
require_relative "produced_files"
require_relative "shell_line"
require_relative "unpack_dir"

module Relspec
  module Builder
    # Builds in a clean chroot with sbuild in unshare mode (no root inside,
    # nothing on this machine changes), on the chroot tarball of the target
    # (Chroot). Build-dependencies come from the distribution (the chroot's
    # sources), the release's own and ancestors' repositories, and the .debs
    # built earlier in this run (--extra-package).
    #
    # A repository reachable over http(s) is an --extra-repository, with its
    # key (--extra-repository-key) when signed and `[trusted=yes]` only when
    # the spec says `trusted: true`. The unshare chroot cannot see this
    # machine's folders, so a local repository's .debs of the target are
    # handed over as --extra-package instead (relspec read and checked that
    # repository when it planned the release).
    class SbuildBackend
      NAME = "sbuild"

      # +distributions+: codename => ReleaseSpec::Distribution; +chroot_cache+: the
      # folder of chroot tarballs (default: relspec's cache); +unpack_dir+:
      # where each build's chroot is unpacked (UnpackDir: tmpfs when there
      # is room); +ccache+: the compiler cache bound into each build's
      # chroot (Ccache), nil for none; +apt_cache+: the .debs downloaded for
      # the builds of a target (AptCache), nil for none; +layer_ids+: [[first
      # uid, count], [first gid, count]] of the subordinate ids sbuild maps
      # the chroot's users to, to build on the target's chroot unpacked once
      # (ChrootLayers; root only), nil to unpack it in every build (or a
      # lambda returning either: read at the first local build, as a Slurm
      # submit host builds nothing here and may have no subordinate ids);
      # +dependency_layers+: builds on layers share a layer of their exact
      # build-dependency set (DependencyLayers; RELSPEC_DEPENDENCY_LAYERS=off
      # for none, as a bench does to compare); +layer_bound+: the folder of
      # a target's layers => DependencyLayers' options that bound them
      # (DependencyLayers.bound: RELSPEC_LAYER_BUDGET read once, here).
      def initialize(tool, distributions, chroot_cache: nil, unpack_dir: UnpackDir.new,
                     ccache: Ccache.from_environment, apt_cache: AptCache.from_environment,
                     layer_ids: -> { SbuildBackend.layer_ids },
                     dependency_layers: ENV["RELSPEC_DEPENDENCY_LAYERS"] != "off",
                     layer_bound: DependencyLayers.bound(ENV.fetch(LayerBudget::VARIABLE, nil)))
        @tool = tool
        @distributions = distributions
        @chroot_cache = chroot_cache
        @unpack_dir = unpack_dir
        @ccache = ccache
        @apt_cache = apt_cache
        @layer_ids = layer_ids
        @dependency_layers = dependency_layers
        @layer_bound = layer_bound
        @dependencies = {}
        @chroots = {}
        @layers = {}
        @lock = Mutex.new
      end

      # The subordinate id ranges of root, which lays chroots out in layers
      # (mounting an overlay needs root); nil for anybody else, and when
      # RELSPEC_CHROOT_LAYERS=off in +env+ (a kernel without overlayfs, or a
      # bench timing the tarball unpacked in every build).
      def self.layer_ids(uid = Process.uid, env: ENV, subuid: "/etc/subuid", subgid: "/etc/subgid")
        return nil unless uid.zero? && env["RELSPEC_CHROOT_LAYERS"] != "off"

        user = Etc.getpwuid(uid).name
        [ChrootLayers.range(subuid, user), ChrootLayers.range(subgid, user)]
      end

      def name
        NAME
      end

      # Called once when the run ends: nothing of it stays on tmpfs.
      def finish
        @unpack_dir.close
      end

      # Called when the run has finished +target+'s builds: its layers (the
      # lower one and the build-dependency layers) go, so that the next
      # target starts with their room free.
      def finish_target(target)
        layers = @lock.synchronize do
          @dependencies.delete(target.to_s)
          @layers.delete(target.to_s)
        end
        FileUtils.rm_rf(layers.folder) if layers
      end

      # Makes the target's chroot tarball unless it exists; true if it did.
      # The caches' folders first: a folder relspec must refuse stops the
      # run before any chroot is made.
      def prepare(target, log:)
        @ccache&.prepare
        @apt_cache&.prepare
        chroot(target).ensure(log)
      end

      def build(request)
        prepare(request.target, log: request.log)
        Dir.mktmpdir("relspec-sbuild") do |work|
          layers = layers(request.target)
          layers ? run_layered(layers, request, work) : run(request, work, command(request, work))
          ProducedFiles.collect(work, request.output_dir)
        end
      end

      # sbuild's command line for +request+, building in the folder +work+
      # on the chroot tarball +tarball+; the same on this machine and in a
      # Slurm job. +local_debs+ may name folders of .debs (sbuild takes
      # every .deb in them). +installed+: the chroot holds exactly the
      # build's build-dependencies (DependencyLayers::Installed#complete):
      # sbuild's null resolver, which installs nothing, and no packages
      # to resolve from (docs/build.md, "No resolver on an exact layer").
      def command(request, work, tarball = chroot(request.target).path, installed: false)
        sources = installed ? ["--build-dep-resolver=null"] : [*repository_options(request), *extra_packages(request)]
        ["sbuild", "--chroot-mode=unshare", "--chroot=#{tarball}",
         "--dist=#{request.target.codename}", "--arch=#{request.target.arch}", "--arch-all", "--no-source",
         "--no-run-lintian", "--no-run-piuparts", "--no-run-autopkgtest", "--no-apt-upgrade",
         "--no-apt-distupgrade", "--nolog", "--build-dir=#{work}", *sources, request.dsc]
      end

      # The shell lines of a Slurm job that builds +request+ in +work+
      # (Slurm::JobScript runs them in that folder).
      def job_steps(request, work)
        [ShellLine.join(command(request, work))]
      end

      # The shell lines of the job that makes the target's chroot tarball
      # on a node, unless the shared folder has it.
      def prepare_steps(target)
        chroot(target).job_steps
      end

      private

      # Runs sbuild; +lines+: more lines of its configuration. In a Slurm job
      # (#job_steps) none of them: its nodes have other folders. +downloads+:
      # whether apt may download build-dependencies (the target's kept .debs).
      def run(request, work, command, lines = [], downloads: true)
        apt = downloads ? @apt_cache&.config_lines(request.target) : nil
        environment = @unpack_dir.environment([*lines, *@ccache&.config_lines, *apt])
        @tool.run(request.source, command, log: request.log, chdir: work, env: environment, name: "sbuild")
      end

      # Runs sbuild on a layer of its own over the target's unpacked chroot,
      # and over the layer of its build-dependencies when there is one.
      def run_layered(layers, request, work)
        lower = layers.lower(@tool, request.source, request.log)
        with_dependencies(request, layers, lower) do |installed|
          lowers = installed&.folder ? "#{installed.folder}:#{lower}" : lower
          complete = installed&.complete || false
          layers.layer do |upper, overlay_work, merged|
            sbuild = command(request, work, layers.empty_tarball, installed: complete)
            run(request, work, layers.wrap(sbuild, lowers, upper, overlay_work, merged), layers.config_lines(merged),
                downloads: !complete)
          end
        end
      end

      # Runs the block with what +request+ finds installed over +lower+
      # (DependencyLayers::Installed, nil for nothing), its layer in use
      # until the block ends.
      def with_dependencies(request, layers, lower, &)
        dependencies = dependencies(request.target, layers)
        return yield nil unless dependencies

        dependencies.use(@tool, request, lower, &)
      end

      # The target's ChrootLayers, nil when builds unpack the tarball.
      def layers(target)
        @lock.synchronize do
          @layer_ids = @layer_ids.call if @layer_ids.respond_to?(:call)
          next nil unless @layer_ids

          @layers[target.to_s] ||= ChrootLayers.new(chroot(target).path, @unpack_dir.folder(target.dir_name),
                                                    uids: @layer_ids[0], gids: @layer_ids[1])
        end
      end

      # The target's DependencyLayers, nil when builds install their own.
      def dependencies(target, layers)
        return nil unless @dependency_layers

        @lock.synchronize do
          @dependencies[target.to_s] ||=
            DependencyLayers.new(layers.folder, namespace: layers.namespace, arch: target.arch,
                                                owner: [layers.uids.first, layers.gids.first],
                                                archives: @apt_cache&.target_folder(target),
                                                depends: @ccache ? [Ccache::PACKAGE] : [],
                                                **@layer_bound.call(layers.folder))
        end
      end

      def chroot(target)
        @chroots[target.to_s] ||= Chroot.new(target, @distributions[target.codename], @tool,
                                             **(@chroot_cache ? { cache_dir: @chroot_cache } : {}))
      end

      def repository_options(request)
        request.repositories.flat_map do |repository|
          next local_packages(repository, request.target) if repository.local?

          options = repository.trusted ? ["[trusted=yes]"] : []
          line = ["deb", *options, repository.uri, repository.suite, *repository.components].join(" ")
          ["--extra-repository=#{line}", *(repository.keyring ? ["--extra-repository-key=#{repository.keyring}"] : [])]
        end
      end

      def extra_packages(request)
        request.local_debs.map { |deb| "--extra-package=#{deb}" }
      end

      # The .debs a local repository holds for the target (apt picks by version).
      def local_packages(repository, target)
        repository.pool_debs(target).map { |deb| "--extra-package=#{deb}" }
      end
    end
  end
end
