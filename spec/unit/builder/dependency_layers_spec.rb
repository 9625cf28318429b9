# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/dependency_layers"
require "relspec/builder/request"

# Which builds share a build-dependency layer. The tool stands in for apt
# here, answering each simulation with the Inst lines a test gives per .dsc
# (apt resolves for real in spec/relspec/builder/build_dependency_set_spec.rb,
# the layers are made and used in spec/relspec/builder/sbuild_spec.rb).
RSpec.describe Relspec::Builder::DependencyLayers do
  around do |example|
    Dir.mktmpdir("dependency-layers-unit") { |dir| @dir = dir and example.run }
  end

  # apt's answers: .dsc => Inst lines; installs: the install commands run
  let(:tool) do
    Class.new do
      attr_reader :installs

      def initialize(answers, fail_install: false)
        @answers = answers
        @installs = []
        @fail_install = fail_install
      end

      def run(source, command, log:, name:, **)
        case name
        when "indexing the build's .debs" then File.write(File.join(command[4], "Packages"), "")
        when "resolving the build-dependencies" then File.write(log, @answers.fetch(source))
        when "installing the build-dependency layer"
          @installs << command
          raise Relspec::BuildError, "#{source}: apt failed" if @fail_install
        end
      end
    end
  end

  def layers(depends: [], **bound)
    described_class.new(@dir, namespace: %w[unshare --user], archives: nil, arch: "amd64", owner: [Process.uid, Process.gid],
                              depends: depends, **bound)
  end

  gib = 1024**3

  # Layers bounded to +budget+ GB, each measured 1 GB, with +room+ ([free, available]).
  def bounded(budget, room: [nil, nil])
    layers(budget: Relspec::Builder::LayerBudget.new(budget: budget * (1024**3)), room: -> { room },
           measure: ->(_dir) { 1024**3 })
  end

  def request(source, repositories: [], more: "")
    dsc = File.join(@dir, "#{source}.dsc")
    File.write(dsc, "Source: #{source}\nBuild-Depends: debhelper-compat (= 13),\n cmake\n#{more}")
    Relspec::Builder::Request.new(source: source, version: "1", dsc: dsc, target: Relspec::Target.new("bookworm", "amd64"),
                                  repositories: repositories, local_debs: [], output_dir: @dir,
                                  log: File.join(@dir, "#{source}.log"))
  end

  cmake = "Inst cmake (3.25.1-1 Debian:12.11/stable [amd64])\n"
  base = "Inst rel-base (2:1.0-1 localhost [all])\n"

  it "makes a layer per exact set, once, and gives it to every build of that set only" do
    apt = tool.new({ "a" => cmake + base, "b" => base + cmake, "c" => cmake, "d" => cmake.sub("3.25.1-1", "3.25.1-2") + base })
    dependency_layers = layers
    installed = %w[a b c d].map { |source| dependency_layers.for(apt, request(source), "/run/lower") }
    # each the whole of its build's needs: sbuild resolves nothing
    expect(installed.map(&:complete)).to eq([true] * 4)
    found = installed.map(&:folder)
    expect(found[0]).to eq(found[1])
    expect(found.uniq.size).to eq(3)
    expect(found).to all(satisfy { |dir| File.basename(dir) == "upper" && File.directory?(dir) })
    expect(apt.installs.size).to eq(3)
    # exactly the set, by name and version (an architecture-independent package as apt names it)
    expect(apt.installs.first.last(2)).to eq(["cmake=3.25.1-1", "rel-base=2:1.0-1"])
    expect(apt.installs.first).to include("/run/lower")
    # chroot into the layer's merged folder runs the install script
    command = apt.installs.first
    at = command.index { |part| part.include?('exec chroot "$@"') }
    expect(command[at + 1, 4]).to eq(["sh", File.join(File.dirname(found[0]), "merged"), "sh", "-c"])
    # with the device nodes and /proc of every sbuild session (the lower layer's refresh has the same)
    expect(command[at]).to start_with(Relspec::Builder::ChrootLayers::SYSTEM_MOUNTS)
    expect(apt.installs.first.join(" ")).to include("apt-get install --yes --no-install-recommends")
    expect(File.read(File.join(@dir, "b.log"))).to match(/^relspec: build-dependency layer \h{16} \(2 packages\) in .*\n/)
    expect(File.read(File.join(@dir, "b.log"))).to end_with("relspec: all build-dependencies installed: sbuild's null resolver\n")
    # the simulation's scratch folders are gone
    expect(Dir.children(@dir).grep(/\Adeps-/).size).to eq(3)
  end

  it "resolves the .dsc's Build-Depends, each field on one line" do
    apt = tool.new({ "a" => cmake })
    layers.for(apt, request("a"), "/run/lower")
    expect(apt.installs.size).to eq(1)
    seen = []
    apt.define_singleton_method(:run) do |_source, command, **options|
      seen << command if options[:name] == "resolving the build-dependencies"
      File.write(options[:log], "") if options[:name] == "resolving the build-dependencies"
      File.write(File.join(command[4], "Packages"), "") if options[:name] == "indexing the build's .debs"
    end
    expect(layers.for(apt, request("a"), "/run/lower").folder).to be_nil
    expect(seen.first.last(2)).to eq(["debhelper-compat (= 13), cmake", "build-essential, fakeroot"])
    # and what sbuild adds to every build (its $manual_depends): the null
    # resolver must find it installed too
    layers(depends: ["ccache"]).for(apt, request("a"), "/run/lower")
    expect(seen.last.last(3)).to eq(["debhelper-compat (= 13), cmake", "ccache", "build-essential, fakeroot"])
  end

  it "gives no layer but the null resolver when the set is empty (all in the lower layer)" do
    installed = layers.for(tool.new({ "e" => "" }), request("e"), "/run/lower")
    expect([installed.folder, installed.complete]).to eq([nil, true])
    expect(installed).to be_frozen
    expect(File.read(File.join(@dir, "e.log"))).to eq("relspec: no build-dependency layer: none to install\n" \
                                                      "relspec: all build-dependencies installed: sbuild's null resolver\n")
  end

  it "keeps sbuild's resolver for a .dsc with Build-Conflicts (apt would remove what conflicts), on the layer still" do
    apt = tool.new({ "a" => cmake, "e" => "", "n" => cmake })
    dependency_layers = layers
    with_layer = dependency_layers.for(apt, request("a", more: "Build-Conflicts-Indep: libfoo-dev\n"), "/run/lower")
    expect(with_layer.complete).to be(false)
    expect(File.basename(with_layer.folder)).to eq("upper")
    expect(File.read(File.join(@dir, "a.log"))).not_to include("null resolver")
    without = dependency_layers.for(apt, request("e", more: "Build-Conflicts: libfoo-dev\n"), "/run/lower")
    expect([without.folder, without.complete]).to eq([nil, false])
    # an empty field conflicts with nothing
    expect(dependency_layers.for(apt, request("n", more: "Build-Conflicts-Arch: \n"), "/run/lower").complete).to be(true)
  end

  it "gives none when the set cannot be known here or its layer cannot be made (and tries that once)" do
    remote = Relspec::Builder::Repository.new(uri: "http://example.org/r", suite: "bookworm", components: ["main"])
    apt = tool.new({ "a" => cmake, "f" => "Inst rel-x (1;x localhost [all])\n" })
    expect(layers.for(apt, request("a", repositories: [remote]), "/run/lower")).to be_nil
    expect(layers.for(apt, request("f"), "/run/lower")).to be_nil
    expect(File.read(File.join(@dir, "f.log"))).to include('relspec: no build-dependency layer: f: apt would install a package with the version "1;x"')
    expect(apt.installs).to be_empty

    failing = tool.new({ "a" => cmake, "b" => cmake }, fail_install: true)
    dependency_layers = layers
    expect(%w[a b].map { |source| dependency_layers.for(failing, request(source), "/run/lower") }).to eq([nil, nil])
    expect(failing.installs.size).to eq(1)
    expect(File.read(File.join(@dir, "b.log"))).to include("could not be made, sbuild installs them")
    expect(Dir.children(@dir).grep(/\Adeps-/)).to be_empty
  end

  it "gives up the least recently used layer no build uses to stay within the budget, never one in use" do
    apt = tool.new({ "a" => cmake, "b" => base, "c" => cmake + base, "d" => cmake, "e" => base })
    dependency_layers = bounded(2)
    first = dependency_layers.for(apt, request("a"), "/run/lower")
    second = dependency_layers.for(apt, request("b"), "/run/lower")
    dependency_layers.release(first)
    # a's layer is unused and the older: it goes, b's (in use) stays
    third = dependency_layers.for(apt, request("c"), "/run/lower")
    expect(third.folder).to be_a(String)
    expect(File.directory?(first.folder)).to be(false)
    expect(File.directory?(second.folder)).to be(true)
    expect(File.read(File.join(@dir, "c.log"))).to match(/^relspec: build-dependency layer \h{16} \(1.0 GB, unused\) removed to make room\n/)
    # both in use: no room for a's set again, and nothing is removed
    fourth = dependency_layers.for(apt, request("d"), "/run/lower")
    expect(fourth).to be_nil
    expect(File.read(File.join(@dir, "d.log"))).to match(
      /^relspec: no build-dependency layer \h{16}: no room \(the layers in use take 2.0 GB, a new one about 1.0 GB, of a budget of 2.0 GB; /
    )
    expect([second.folder, third.folder]).to all(satisfy { |dir| File.directory?(dir) })
    # once b's build ends its layer may go; a's set is made again
    dependency_layers.release(second)
    expect(dependency_layers.for(apt, request("d"), "/run/lower").folder).to eq(first.folder)
    expect(File.directory?(second.folder)).to be(false)
    expect(apt.installs.size).to eq(4)
  end

  it "keeps a floor free on the layers' file system and in memory" do
    apt = tool.new({ "a" => cmake })
    expect(bounded(8, room: [20 * gib, (6 * gib) + 1]).for(apt, request("a"), "/run/lower")).to be_nil
    expect(File.read(File.join(@dir, "a.log"))).to include("6.0 GB of memory available; 6.0 GB must stay free)")
    expect(bounded(8, room: [20 * gib, 8 * gib]).for(apt, request("a"), "/run/lower").folder).to be_a(String)
  end

  it "counts a layer in use while #use's block runs, also when it raises" do
    apt = tool.new({ "a" => cmake, "b" => base })
    dependency_layers = bounded(1)
    expect do
      dependency_layers.use(apt, request("a"), "/run/lower") do |installed|
        expect(installed.folder).to be_a(String)
        # in use: b's set finds no room
        expect(dependency_layers.for(apt, request("b"), "/run/lower")).to be_nil
        raise Relspec::BuildError, "sbuild failed"
      end
    end.to raise_error(Relspec::BuildError)
    expect(dependency_layers.for(apt, request("b"), "/run/lower").folder).to be_a(String)
  end
end
