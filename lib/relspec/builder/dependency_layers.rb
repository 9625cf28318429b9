# frozen_string_literal: true

require "fileutils"
require "open3"
require "tmpdir"
require_relative "../apt/deb822"
require_relative "../error"
require_relative "apt_cache"
require_relative "build_dependency_set"
require_relative "chroot_layers"
require_relative "deb_index"
require_relative "layer_budget"
require_relative "unpack_dir"

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
    #
    # The kept layers are bounded (LayerBudget): before one is made, those
    # no build uses are given up, least recently used first, and when that
    # cannot make room the build goes without one. A layer is in use from
    # #for until #release (#use does both), counted under the lock.
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
      # its core ones (its $manual_depends: ccache when builds use it);
      # +budget+: the bound on the kept layers (LayerBudget), nil for none;
      # +room+: [bytes free on the layers' file system, bytes of memory
      # available or nil when not on tmpfs], either nil when unknown
      # (DependencyLayers.bound gives it with the budget; asked only then);
      # +measure+: a layer's size in bytes.
      def initialize(folder, namespace:, archives:, arch:, owner:, depends: [], budget: nil,
                     room: -> { [nil, nil] }, measure: DependencyLayers.method(:measure))
        @folder = folder
        @budget = budget
        @room = room
        @measure = measure
        @estimate = LayerBudget::ESTIMATE
        @used = 0
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
      # +key+: the set's, nil when no layer is laid (#release).
      Installed = Struct.new(:folder, :complete, :key, keyword_init: true)

      # Bytes of +dir+ (du: what a tmpfs layer takes of memory).
      def self.measure(dir)
        output, status = Open3.capture2("du", "-s", "-x", "-B1", dir, err: File::NULL)
        status.success? ? output.to_i : 0
      end

      # [free bytes, available memory] for layers in +folder+; memory
      # counts only when the folder is on +tmpfs+.
      def self.room(folder, tmpfs:, meminfo: "/proc/meminfo")
        [UnpackDir.free_bytes(folder), tmpfs ? UnpackDir.available_memory(meminfo) : nil]
      end

      def self.tmpfs?(folder)
        output, status = Open3.capture2("stat", "-f", "-c", "%T", folder, err: File::NULL)
        status.success? && output.strip == "tmpfs"
      end

      # The folder of a target's layers => the options that bound them
      # (LayerBudget.bytes of its file system, and how its room is asked;
      # whether it is tmpfs is asked once: it does not change in a run;
      # +override+: the text of RELSPEC_LAYER_BUDGET, refused here, before
      # any build, when no size).
      def self.bound(override)
        bytes = override && LayerBudget.parse(override)
        lambda do |folder|
          tmpfs = tmpfs?(folder)
          { budget: LayerBudget.new(budget: LayerBudget.bytes(UnpackDir.size_bytes(folder), tmpfs: tmpfs, override: bytes)),
            room: -> { room(folder, tmpfs: tmpfs) } }
        end
      end

      # What +request+ finds installed over +lower+ (the lower layer's
      # folder): an Installed, nil when sbuild must resolve and install the
      # build-dependencies itself; +tool+ runs apt into +request+'s log.
      # The layer is the build's until #release.
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

      # Runs the block with #for's answer, released when the block ends.
      def use(tool, request, lower)
        installed = self.for(tool, request, lower)
        yield installed
      ensure
        release(installed) if installed
      end

      # The build given +installed+ (#for) no longer runs over its layer.
      def release(installed)
        return unless installed.key

        @lock.synchronize { @sets.fetch(installed.key)[:users] -= 1 }
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
        Installed.new(folder: folder, complete: complete, key: folder && set.key).freeze
      end

      # One lock per set: builds of other sets go on beside it. The layer
      # is taken (counted in use) under the run's lock, where eviction
      # happens, so no build is given a layer being removed.
      def layer(tool, request, lower, index, set)
        slot = @lock.synchronize { @sets[set.key] ||= { lock: Mutex.new, dir: nil, users: 0, used: 0 } }
        slot[:lock].synchronize do
          dir = @lock.synchronize { take(slot) }
          unless dir || slot[:dir] == :failed
            return nil unless reserve(request.log, set, slot)

            made = make(tool, request, lower, index, set)
            # measured outside the lock (du reads the whole layer); only a budget needs it
            bytes = made && @budget ? @measure.call(made) : 0
            dir = @lock.synchronize { settle(slot, made, bytes) }
          end
          note(request.log, dir ? "in #{dir}" : "could not be made, sbuild installs them", set)
          dir
        end
      end

      # +slot+'s folder, counted in use; nil when it has none (yet, or any more).
      def take(slot)
        return nil unless slot[:dir].is_a?(String)

        slot[:users] += 1
        slot[:used] = (@used += 1)
        slot[:dir]
      end

      # Records +made+ (a layer's folder of +bytes+, nil when apt failed) in +slot+: taken.
      def settle(slot, made, bytes)
        slot[:making] = nil
        unless made
          slot[:dir] = :failed
          return nil
        end

        slot[:dir] = made
        slot[:bytes] = bytes
        @estimate = bytes if bytes.positive?
        take(slot)
      end

      # Room for +slot+'s new layer under the budget, made by giving up
      # layers no build uses; false (and the log says why) when none can be.
      def reserve(log, set, slot)
        return true unless @budget

        evicted = []
        made = @lock.synchronize do
          free, available = @room.call
          decision = @budget.decide(kept, estimate: @estimate, free: free, available: available)
          if decision.make
            evicted = decision.evict.map { |key| evict(log, key) }
            slot[:making] = @estimate
          else
            say(log, "no build-dependency layer #{set.key[0, 16]}: #{decision.reason}")
          end
          decision.make
        end
        # given up under the lock (no build can take them any more), removed outside it
        FileUtils.rm_rf(evicted)
        made
      end

      # The layers kept or being made, for LayerBudget.
      def kept
        @sets.filter_map do |key, slot|
          next unless slot[:dir].is_a?(String) || slot[:making]

          LayerBudget::Layer.new(key: key, bytes: slot[:bytes] || slot[:making], used: slot[:used],
                                 in_use: slot[:users].positive? || !slot[:making].nil?)
        end
      end

      # Gives up +key+'s layer (no build uses it): a later build of its set
      # makes it again. Its folder, for the caller to remove.
      def evict(log, key)
        slot = @sets.fetch(key)
        folder = File.dirname(slot[:dir])
        say(log, "build-dependency layer #{key[0, 16]} (#{LayerBudget.human(slot[:bytes])}, unused) removed to make room")
        slot[:dir] = slot[:bytes] = nil
        folder
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
