# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/sbuild_backend"
require "relspec/builder/request"

# What the sbuild backend hands its tool for one build. The tool is a
# recorder here (the real sbuild run is spec/relspec/builder/sbuild_spec.rb).
RSpec.describe Relspec::Builder::SbuildBackend do
  let(:recorder) do
    Struct.new(:runs) do
      def run(source, command, log:, chdir: nil, env: {}, stdin: nil, name: nil)
        runs << { source: source, command: command, log: log, chdir: chdir, env: env, stdin: stdin, name: name }
      end
    end
  end

  # A folder of chroot tarballs holding bookworm/amd64's (empty: the tool never reads it).
  def tarball_cache(dir)
    File.join(dir, "chroots").tap do |cache|
      FileUtils.mkdir_p(cache)
      File.write(File.join(cache, "bookworm-amd64.tar.zst"), "")
    end
  end

  # UnpackDir's part for layers: the run's folders below +root+; records the
  # configuration lines of every build (+extras+, the last one +extra+).
  let(:layer_folders) do
    Class.new do
      attr_reader :extras

      def initialize(root)
        @root = root
        @extras = []
      end

      def folder(name)
        File.join(@root, name).tap { |path| FileUtils.mkdir_p(path) }
      end

      def environment(extra)
        @extras << extra
        {}
      end

      def extra
        @extras.last
      end
    end
  end

  it "runs sbuild with the environment of where the chroot is unpacked, of the compiler cache and of the target's apt download cache" do
    Dir.mktmpdir do |dir|
      cache = tarball_cache(dir)
      tool = recorder.new([])
      unpack = Class.new do
        attr_reader :extra

        def environment(extra)
          @extra = extra
          { "SBUILD_CONFIG" => "/dev/shm/x/sbuild.conf" }
        end
      end.new
      ccache = Relspec::Builder::Ccache.new(File.join(dir, "ccache"), owner: [Process.uid, Process.gid])
      folder = Relspec::Builder::BuildUserFolder.new(File.join(dir, "apt"), owner: [Process.uid, Process.gid],
                                                                            what: "apt download cache", variable: "V")
      apt_cache = Relspec::Builder::AptCache.new(folder)
      backend = described_class.new(tool, {}, chroot_cache: cache, unpack_dir: unpack, ccache: ccache,
                                              apt_cache: apt_cache, layer_ids: nil)
      request = Relspec::Builder::Request.new(source: "rock-r-a", version: "1.0-1", dsc: "/in/rock-r-a_1.0-1.dsc",
                                              target: Relspec::Target.new("bookworm", "amd64"), repositories: [],
                                              local_debs: [], output_dir: File.join(dir, "out"), log: File.join(dir, "log"))
      allow(Relspec::Builder::Chroot).to receive(:host_arch).and_return("amd64")
      backend.build(request)
      run = tool.runs.fetch(0)
      expect(run[:env]).to eq("SBUILD_CONFIG" => "/dev/shm/x/sbuild.conf")
      expect(run[:command]).to include("sbuild", "--chroot-mode=unshare", "/in/rock-r-a_1.0-1.dsc")
      # the caches' lines go into that file, not onto the command line
      target = Relspec::Target.new("bookworm", "amd64")
      expect(unpack.extra).to eq(ccache.config_lines + apt_cache.config_lines(target))
      expect(unpack.extra.join).to include("#{dir}/apt/bookworm-amd64")
      expect(run[:command].join(" ")).not_to include("ccache", "relspec-apt", "#{dir}/apt")
    end
  end

  it "builds on a layer of its own over the target's chroot, unpacked once, and removes the layer after the build" do
    Dir.mktmpdir do |dir|
      cache = tarball_cache(dir)
      tarball = File.join(cache, "bookworm-amd64.tar.zst")
      tool = recorder.new([])
      folders = File.join(dir, "run")
      unpack = layer_folders.new(folders)
      ids = [[Process.uid, 1], [Process.gid, 1]]
      backend = described_class.new(tool, {}, chroot_cache: cache, unpack_dir: unpack, ccache: nil, apt_cache: nil,
                                              layer_ids: ids, dependency_layers: false)
      allow(Relspec::Builder::Chroot).to receive(:host_arch).and_return("amd64")
      2.times do |index|
        request = Relspec::Builder::Request.new(source: "rock-r-#{index}", version: "1.0-1", dsc: "/in/r_1.0-1.dsc",
                                                target: Relspec::Target.new("bookworm", "amd64"), repositories: [],
                                                local_debs: [], output_dir: File.join(dir, "out#{index}"),
                                                log: File.join(dir, "log"))
        backend.build(request)
      end
      lower = File.join(folders, "bookworm-amd64", "lower")
      unpacking, refreshing, first, second = tool.runs
      expect(tool.runs.size).to eq(4)
      expect([refreshing[:name], refreshing[:command].last]).to eq(["refreshing the chroot's package lists", lower])
      expect([unpacking[:stdin], unpacking[:name], unpacking[:command].last]).to eq([tarball, "unpacking the chroot", lower])
      expect(unpacking[:command].first(3)).to eq(["unshare", "--user", "--map-users=#{Process.uid},0,1"])
      [first, second].each do |run|
        command = run[:command]
        expect(command.first(4)).to eq(["unshare", "--mount", "--propagation", "private"])
        layer_lower, upper, work, merged = command[9, 4]
        expect(layer_lower).to eq(lower)
        expect([upper, work, merged].map { |path| File.basename(path) }).to eq(%w[upper work merged])
        expect(command).to include("sbuild", "--chroot=#{File.join(folders, 'bookworm-amd64', 'empty.tar')}")
        expect(run[:name]).to eq("sbuild")
        # the layer is gone, the lower layer stays for the next build
        expect(File.exist?(File.dirname(upper))).to be(false)
      end
      expect(first[:command][10]).not_to eq(second[:command][10])
      merged = second[:command][12]
      expect(unpack.extra.first).to eq("unshift @{$unshare_bind_mounts}, { directory => '#{merged}', mountpoint => '/' };")
      # sbuild's steps a throw-away layer makes useless are left out
      expect(unpack.extra.drop(1)).to include("$apt_update = 0;", "$purge_session = 'never';",
                                              "$unshare_tmpdir_template = '#{File.dirname(merged)}/session.XXXXXXXXXX';")
      expect(File.size(File.join(folders, "bookworm-amd64", "empty.tar"))).to eq(1024)
    end
  end

  # The build-dependency layers' resolution, answered per source as apt
  # would (DependencyLayers resolves for real in sbuild_spec.rb).
  let(:resolver) do
    Class.new do
      attr_reader :runs

      def initialize(answers)
        @answers = answers
        @runs = []
      end

      def run(source, command, log:, chdir: nil, env: {}, stdin: nil, name: nil)
        @runs << { source: source, command: command, env: env, name: name }
        case name
        when "indexing the build's .debs" then File.write(File.join(command[4], "Packages"), "")
        when "resolving the build-dependencies" then File.write(log, @answers.fetch(source))
        end
      end
    end
  end

  it "runs sbuild's null resolver, with no .debs to resolve from nor any to download, when the chroot holds the exact set" do
    Dir.mktmpdir do |dir|
      cache = tarball_cache(dir)
      unpack = layer_folders.new(File.join(dir, "run"))
      folder = Relspec::Builder::BuildUserFolder.new(File.join(dir, "apt"), owner: [Process.uid, Process.gid],
                                                                            what: "apt download cache", variable: "V")
      apt_cache = Relspec::Builder::AptCache.new(folder)
      deb = File.join(dir, "rock-r-base_1.0-1_all.deb")
      File.write(deb, "")
      cmake = "Inst cmake (3.25.1-1 Debian:12.11/stable [amd64])\n"
      tool = resolver.new({ "empty" => "", "cmake" => cmake, "conflicts" => cmake })
      ccache = Relspec::Builder::Ccache.new(File.join(dir, "ccache"), owner: [Process.uid, Process.gid])
      # bounded as on a file system with room (df and du are not run here)
      bound = { budget: Relspec::Builder::LayerBudget.new(budget: 1024**3), room: -> { [nil, nil] }, measure: ->(_dir) { 1 } }
      backend = described_class.new(tool, {}, chroot_cache: cache, unpack_dir: unpack, ccache: ccache, apt_cache: apt_cache,
                                              layer_ids: [[Process.uid, 1], [Process.gid, 1]], layer_bound: ->(_folder) { bound })
      allow(Relspec::Builder::Chroot).to receive(:host_arch).and_return("amd64")
      sbuilds = %w[empty cmake conflicts].map do |source|
        dsc = File.join(dir, "#{source}.dsc")
        File.write(dsc, "Source: #{source}\nBuild-Depends: cmake\n#{"Build-Conflicts: foo\n" if source == 'conflicts'}")
        backend.build(Relspec::Builder::Request.new(source: source, version: "1.0-1", dsc: dsc,
                                                    target: Relspec::Target.new("bookworm", "amd64"), repositories: [],
                                                    local_debs: [deb], output_dir: File.join(dir, "out-#{source}"),
                                                    log: File.join(dir, "#{source}.log")))
        tool.runs.select { |run| run[:name] == "sbuild" }.last[:command]
      end
      empty, on_layer, conflicts = sbuilds
      # the set holds what sbuild adds for ccache ($manual_depends)
      simulation = tool.runs.find { |run| run[:name] == "resolving the build-dependencies" }[:command]
      expect(simulation.last(3)).to eq(["cmake", "ccache", "build-essential, fakeroot"])
      # the set all in the lower layer, or in the layer under the build
      [empty, on_layer].each do |command|
        expect(command).to include("--build-dep-resolver=null")
        expect(command.grep(/--extra-package/)).to be_empty
      end
      expect(empty[9]).to eq(File.join(dir, "run", "bookworm-amd64", "lower"))
      expect(on_layer[9]).to match(%r{/deps-\h{16}/upper:.*/lower\z})
      # nothing to download: no apt cache bound in, no .debs linked or kept
      expect(unpack.extras[0].join).not_to include("relspec-apt", "#{dir}/apt")
      expect(unpack.extras[1].join).not_to include("relspec-apt", "#{dir}/apt")
      expect(unpack.extras[1]).to include(*ccache.config_lines)
      # Build-Conflicts: apt removes what conflicts, on the same layer
      expect(conflicts).not_to include("--build-dep-resolver=null")
      expect(conflicts).to include("--extra-package=#{deb}")
      expect(conflicts[9]).to eq(on_layer[9])
      expect(unpack.extras[2]).to end_with(*ccache.config_lines, *apt_cache.config_lines(Relspec::Target.new("bookworm", "amd64")))

      # the target's builds have ended: its layers go (the lower one and
      # the build-dependency layer), another target's stay
      File.write(File.join(dir, "run", "trixie-amd64"), "")
      backend.finish_target(Relspec::Target.new("bookworm", "amd64"))
      expect(Dir.children(File.join(dir, "run"))).to eq(["trixie-amd64"])
    end
  end

  it "lays chroots out in layers for root, with its subordinate ranges, unless RELSPEC_CHROOT_LAYERS=off" do
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "subuid"), "root:100000:65536\n")
      File.write(File.join(dir, "subgid"), "root:200000:1000\n")
      files = { subuid: File.join(dir, "subuid"), subgid: File.join(dir, "subgid") }
      expect(described_class.layer_ids(0, env: {}, **files)).to eq([[100_000, 65_536], [200_000, 1000]])
      expect(described_class.layer_ids(0, env: { "RELSPEC_CHROOT_LAYERS" => "off" }, **files)).to be_nil
      expect(described_class.layer_ids(1000, env: {}, **files)).to be_nil
    end
  end

  it "reads the subordinate ids only for a local build (a Slurm submit host may have none)" do
    Dir.mktmpdir do |dir|
      allow(Relspec::Builder::Chroot).to receive(:host_arch).and_return("amd64")
      allow(described_class).to receive(:layer_ids).and_raise(Relspec::BuildError, "no subordinate ids")
      backend = described_class.new(recorder.new([]), {}, chroot_cache: dir, unpack_dir: nil, ccache: nil, apt_cache: nil)
      request = Relspec::Builder::Request.new(source: "rock-r-a", version: "1.0-1", dsc: "/in/rock-r-a_1.0-1.dsc",
                                              target: Relspec::Target.new("bookworm", "amd64"), repositories: [],
                                              local_debs: [], output_dir: File.join(dir, "out"), log: File.join(dir, "log"))
      expect(backend.job_steps(request, "/work").first).to start_with("sbuild --chroot-mode=unshare")
    end
  end
end
