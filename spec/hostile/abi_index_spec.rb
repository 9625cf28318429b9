# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "../support/build_release"

# `relspec publish` over a damaged ABI index in its own repository
# (<repository>/abi/<target>/index.yml; issue 46 case 7). It used to
# publish the packages and then stop (exit 1) before the osdeps files and
# the status page, and its hint, "publish again", stopped the same way.
# Now the index is read before anything is published and, when it cannot
# be read, made again from the dump files there that build-results.yml
# vouches for (source, file name and SHA256); the publish runs to its end
# and says so. A real release of two packages that install an oroGen type
# registry (dumped by the host build), published into a real reprepro
# repository once; each example damages the index of that publication.
RSpec.describe "relspec publish with a damaged ABI index", order: :defined do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-abi-index")
    registry = File.read(File.expand_path("../fixtures/abi/std.tlb", __dir__))
    @release = BuildRelease.new(@dir, "ix")
    %w[one two].each do |name|
      @release.package("test/#{name}", cmake: "install(FILES #{name}.tlb DESTINATION share/orogen)",
                                       files: { "#{name}.tlb" => registry })
    end
    @release.compile(spec: "repository: { path: ../repos/ix, trusted: true }\n")
    %w[build publish].each do |command|
      run = relspec(command, "specs/ix.yml", "--out", "out", *(command == "build" ? %w[--backend host] : []), chdir: @dir)
      raise "relspec #{command}: #{run.stdout}#{run.stderr}" unless run.status.success?
    end
    @index = File.join(@dir, "repos", "ix", "abi", "bookworm-amd64", "index.yml")
    @published = File.read(@index)
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  let(:page) { File.join(@dir, "repos", "ix", "report", "index.html") }

  def publish
    relspec("publish", "specs/ix.yml", "--out", "out", chdir: @dir)
  end

  # The index is damaged and the status page gone: a publish that stops
  # halfway writes neither again.
  def damage(text)
    File.write(@index, text)
    FileUtils.rm_f(page)
  end

  it "publishes the release to its end, the index made again from the dumps a build vouches for" do
    expect(YAML.safe_load(@published)["dumps"].map { |dump| dump["library"] }).to eq(%w[one.tlb two.tlb])
    damage("relspec_abi_dumps: 1\ndumps:\n  - { package: test/one, library: [\n")
    run = publish
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stderr).to match(/\Athe ABI index #{Regexp.escape(@index)} could not be read \(.*index.yml:\d+:\d+: .*\); made it again from the 2 dumps there that build-results.yml vouches for\n\z/)
    expect(File.read(@index)).to eq(@published)
    expect(File.file?(page)).to be(true)
    expect(run.stdout).to include("status page: ")
  end

  it "leaves out, and names, a dump file no build vouches for" do
    foreign = File.join(File.dirname(@index), "rock-ix-evil", "evil.tlb.abi.xml.gz")
    FileUtils.mkdir_p(File.dirname(foreign))
    File.write(foreign, "not a dump of this release")
    damage("relspec_abi_dumps: 7\n")
    run = publish
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stderr).to end_with("; made it again from the 2 dumps there that build-results.yml vouches for; " \
                                   "left out, as no build vouches for them: rock-ix-evil/evil.tlb.abi.xml.gz\n")
    expect(File.read(@index)).to eq(@published)
    expect(File.file?(page)).to be(true)
  end

  it "publishes again without a word once the index is whole" do
    run = publish
    expect([run.exit_code, run.stderr]).to eq([0, ""])
    expect(File.read(@index)).to eq(@published)
  end
end
