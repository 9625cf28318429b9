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
      def run(source, command, log:, chdir: nil, env: {})
        runs << { source: source, command: command, log: log, chdir: chdir, env: env }
      end
    end
  end

  it "runs sbuild with the environment of where the chroot is unpacked and of the compiler cache" do
    Dir.mktmpdir do |dir|
      cache = File.join(dir, "chroots")
      FileUtils.mkdir_p(cache)
      File.write(File.join(cache, "bookworm-amd64.tar.zst"), "")
      tool = recorder.new([])
      unpack = Class.new do
        attr_reader :extra

        def environment(extra)
          @extra = extra
          { "SBUILD_CONFIG" => "/dev/shm/x/sbuild.conf" }
        end
      end.new
      ccache = Relspec::Builder::Ccache.new(File.join(dir, "ccache"), owner: [Process.uid, Process.gid])
      backend = described_class.new(tool, {}, chroot_cache: cache, unpack_dir: unpack, ccache: ccache)
      request = Relspec::Builder::Request.new(source: "rock-r-a", version: "1.0-1", dsc: "/in/rock-r-a_1.0-1.dsc",
                                              target: Relspec::Target.new("bookworm", "amd64"), repositories: [],
                                              local_debs: [], output_dir: File.join(dir, "out"), log: File.join(dir, "log"))
      allow(Relspec::Builder::Chroot).to receive(:host_arch).and_return("amd64")
      backend.build(request)
      run = tool.runs.fetch(0)
      expect(run[:env]).to eq("SBUILD_CONFIG" => "/dev/shm/x/sbuild.conf")
      expect(run[:command]).to include("sbuild", "--chroot-mode=unshare", "/in/rock-r-a_1.0-1.dsc")
      # the compiler cache's lines go into that file, not onto the command line
      expect(unpack.extra).to eq(ccache.config_lines)
      expect(run[:command].join(" ")).not_to include("ccache")
    end
  end
end
