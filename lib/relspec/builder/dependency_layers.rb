# frozen_string_literal: true

require "fileutils"
require "tmpdir"
require_relative "../apt/deb822"
require_relative "../error"
require_relative "apt_cache"
require_relative "build_dependency_set"
require_relative "chroot_layers"
require_relative "deb_index"

module Relspec
  module Builder
    # Build-dependency layers by exact set (docs/build.md): before a build
    # on a layer, apt resolves its Build-Depends in the target's lower layer
    # (BuildDependencySet, with the .debs the build is given); the first
    # build of a set installs exactly that set into a layer of its own over
    # the lower one, and every later build of this run whose set is equal,
    # package for package and version for version, runs on it as one more
    # lower layer: sbuild then finds its build-dependencies installed. A
    # build of another set never sees the layer, so no build has more than
    # it declares and a missing Build-Depends still fails.
    #
    # Builds of the same set at once: one makes the layer, the others wait
    # for it (a lock per set). A set that cannot be known here (a remote
    # --extra-repository, whose lists only sbuild fetches) or a layer that
    # cannot be made gives nil: the build installs its own, as without.
    class DependencyLayers
      # where the layer's install sees the build's own .debs (empty in a
      # Debian chroot, so binding onto it writes nothing into the layer)
      DEBS = "/mnt"
      # where it sees the target's kept .debs (AptCache; empty in a Debian chroot too)
      KEPT = "/srv"
      CONFLICTS = %w[Build-Conflicts Build-Conflicts-Arch Build-Conflicts-Indep].freeze

      # +folder+: the run's folder of the target's layers (ChrootLayers);
      # +namespace+: unshare's options for the chroot's root
      # (ChrootLayers#namespace); +archives+: the folder of .debs kept for
      # the target (AptCache#target_dir), nil for none; +arch+: the
      # target's architecture; +owner+: [uid, gid] of the chroot's root;
      # +depends+: what sbuild adds to every build's Build-Depends besides
      # its core ones (its $manual_depends: ccache when builds use it).
      def initialize(folder, namespace:, archives:, arch:, owner:, depends: [])
        @folder = folder
        @depends = depends
        @namespace = namespace
        @owner = owner
        @archives = archives
        @arch = arch
        @lock = Mutex.new
        @sets = {}
      end

      # What a build finds installed when its set is known and in place:
      # +folder+, the layer to lay between its own and the lower one (nil
      # when the set is empty: all in the lower layer already); +complete+,
      # true when that is all the build needs (docs/build.md, "No resolver
      # on an exact layer"): sbuild then runs its null resolver.
      Installed = Struct.new(:folder, :complete, keyword_init: true)

      # What +request+ finds installed over +lower+ (the lower layer's
      # folder): an Installed, nil when sbuild must resolve and install the
      # build-dependencies itself; +tool+ runs apt into +request+'s log.
      def for(tool, request, lower)
        return nil unless request.repositories.all?(&:local?)

        fields = dsc_fields(request)
        return nil unless fields

        Dir.mktmpdir("resolve-", @folder) do |scratch|
          index = DebIndex.new(scratch, debs(request))
          set = resolve(tool, request, lower, index, scratch, fields)
          next nil if set.nil?

          installed(request.log, fields, set.empty? ? nil : layer(tool, request, lower, index, set), set)
        end
      end

      private

      # A build's Installed, nil when its set's layer could not be made. A
      # .dsc with Build-Conflicts keeps sbuild's resolver: apt removes a
      # conflicting package of the chroot before the build, which the
      # simulation does not (it resolves the Build-Depends only).
      def installed(log, fields, folder, set)
        return nil if folder.nil? && !set.empty?

        # all in the chroot already: nothing to lay under the build
        say(log, "no build-dependency layer: none to install") if set.empty?
        complete = CONFLICTS.all? { |name| fields[name].to_s.strip.empty? }
        say(log, "all build-dependencies installed: sbuild's null resolver") if complete
        Installed.new(folder: folder, complete: complete).freeze
      end

      # One lock per set: builds of other sets go on beside it.
      def layer(tool, request, lower, index, set)
        slot = @lock.synchronize { @sets[set.key] ||= { lock: Mutex.new, dir: nil } }
        slot[:lock].synchronize do
          slot[:dir] ||= make(tool, request, lower, index, set) || :failed
          note(request.log, slot[:dir] == :failed ? "could not be made, sbuild installs them" : "in #{slot[:dir]}", set)
          slot[:dir] == :failed ? nil : slot[:dir]
        end
      end

      def note(log, what, set)
        say(log, "build-dependency layer #{set.key[0, 16]} (#{set.packages.size} packages) #{what}")
      end

      # Writes +text+ into the build's log; nil.
      def say(log, text)
        File.open(log, "a") { |file| file.puts("relspec: #{text}") }
        nil
      end

      # The .debs the build is given (sbuild's --extra-package).
      def debs(request)
        local = request.local_debs.flat_map do |deb|
          File.directory?(deb) ? Dir.glob(File.join(deb, "*.deb")).sort : [deb]
        end
        request.repositories.flat_map { |repository| repository.pool_debs(request.target) } + local
      end

      def resolve(tool, request, lower, index, scratch, fields)
        lists = File.join(scratch, "lists")
        options = ["-o", "Dir::Etc::sourcelist=#{index.sources}", "-o", "Dir::State::Lists=#{lists}"]
        tool.run(request.source, index.update_command(lower, lists, scratch), log: request.log, name: "indexing the build's .debs")
        # the lower layer's lists beside the .debs' (apt-get update would have removed them)
        Dir.glob(File.join(lower, "var/lib/apt/lists/*")).each do |list|
          File.symlink(list, File.join(lists, File.basename(list))) if File.file?(list) && File.basename(list) != "lock"
        end
        output = File.join(scratch, "simulation")
        tool.run(request.source, BuildDependencySet.simulate_command(lower, scratch, build_depends(fields) + @depends, options),
                 log: output, name: "resolving the build-dependencies")
        BuildDependencySet.from_simulation(File.read(output), source: request.source)
      rescue BuildError, SystemCallError => e
        # sbuild resolves them itself and says what is wrong
        say(request.log, "no build-dependency layer: #{e.message}")
      end

      def dsc_fields(request)
        Apt::Deb822.parse(File.read(request.dsc)).first || {}
      rescue SystemCallError, Apt::Deb822::ParseError => e
        # sbuild reads it itself and says what is wrong
        say(request.log, "no build-dependency layer: #{e.message}")
      end

      # The .dsc's build-dependency fields (sbuild builds with --arch-all).
      def build_depends(fields)
        %w[Build-Depends Build-Depends-Arch Build-Depends-Indep].filter_map do |name|
          fields[name]&.gsub(/\s+/, " ")&.strip
        end.reject(&:empty?)
      end

      # Installs exactly +set+ into a new layer; its folder, nil when apt
      # failed (the partial layer is removed).
      def make(tool, request, lower, index, set)
        dir = File.join(@folder, "deps-#{set.key[0, 16]}")
        upper, work, merged = %w[upper work merged].map { |name| File.join(dir, name) }
        FileUtils.mkdir_p([upper, work, merged], mode: 0o755)
        File.chown(*@owner, upper)
        tool.run(request.source, install_command(lower, upper, work, merged, index, set), log: request.log,
                                                                                          name: "installing the build-dependency layer")
        FileUtils.rm_rf([work, merged])
        upper
      rescue BuildError
        FileUtils.rm_rf(dir)
        nil
      end

      # Installs in the layer as the chroot's root, as sbuild would; the
      # target's kept .debs (AptCache) bound at KEPT and linked into the
      # layer's own archives (apt locks its archives: two layers made at
      # once must not share them), those apt downloaded kept, and the
      # archives emptied: the layer holds the installed packages only.
      def install_command(lower, upper, work, merged, index, set)
        mounts = 'mount -t overlay overlay -o "lowerdir=$1,upperdir=$2,workdir=$3" "$4" && ' \
                 "mount --bind \"$5\" \"$4#{DEBS}\" && " \
                 "{ [ -z \"$6\" ] || mount --bind \"$6\" \"$4#{KEPT}\"; } && shift 6 && exec \"$@\""
        install = "DEBIAN_FRONTEND=noninteractive apt-get install --yes --no-install-recommends " \
                  '-o Dpkg::Options::=--force-confold "$@"'
        install = "#{AptCache.link_script(KEPT)} && #{install} && #{AptCache.keep_script(KEPT)}" if @archives
        ["unshare", "--mount", "--propagation", "private", "--", "sh", "-c", mounts, "sh", lower, upper, work, merged,
         index.dir, @archives.to_s, *@namespace, "--mount", "--pid", "--fork", "--", "sh", "-c",
         "#{ChrootLayers::SYSTEM_MOUNTS} && exec chroot \"$@\"", "sh", merged,
         "sh", "-c", "#{install} && apt-get clean", "sh", *set.packages.map { |package| argument(package, index) }]
      end

      # apt-get install's argument for exactly +package+: the build's own
      # .deb by its path, the others by name and version.
      def argument(package, index)
        file = index.file(package)
        return File.join(DEBS, file) if file

        [@arch, "all"].include?(package.arch) ? "#{package.name}=#{package.version}" : package.to_s
      end
    end
  end
end
