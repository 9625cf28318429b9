# frozen_string_literal: true

require "spec_helper"
require "fileutils"
require "open3"
require "relspec/abi/interface_check"
require "relspec/abi/comparison"
require "relspec/builder/abi_dumper"
require "relspec/builder/host_backend"
require "relspec/builder/request"
require "relspec/builder/tool"
require "relspec/worker_pool"
require_relative "../../support/cutoff_corpus"

# The early cutoff's corpus (issue 45 item 3, docs/abi.md "Early
# cutoff"): a small real C and C++ library package and its dependent,
# built for real with the host backend; every edit of CutoffCorpus::CASES
# is built and its decision asserted against the baseline build. For the
# kept cases, the dependent built against the baseline runs against the
# new library and calls into it.
RSpec.describe "the early cutoff's decision on a corpus of real builds" do
  before(:all) do
    @root = Dir.mktmpdir("relspec-cutoff")
    @tool = Relspec::Builder::Tool.new
    @backend = Relspec::Builder::HostBackend.new(@tool)
    @check = Relspec::Abi::InterfaceCheck.new(compare: Relspec::Abi::Comparison.method(:compare))
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    @base = build("cutoff-lib", "1.0", CutoffCorpus.library)
    @user = build("cutoff-user", "1.0", CutoffCorpus.user, build_depends: ["cutoff-lib"], local: @base)
    cases = {}
    lock = Mutex.new
    # builds mostly wait (dpkg-buildpackage starts a Perl per dh step): a
    # few at once cost about the time of one
    Relspec::WorkerPool.new(3).each(CutoffCorpus::CASES.each_with_index.to_a) do |corpus_case, index|
      files = build("cutoff-lib", "1.0+c#{index + 1}", CutoffCorpus.edited(CutoffCorpus.library, corpus_case.edit))
      verdict = @check.decide("cutoff/lib", old: side("1.0", @base), new: side("1.0+c#{index + 1}", files))
      lock.synchronize { cases[corpus_case.name] = [verdict, files] }
    end
    @cases = cases
    @seconds = Process.clock_gettime(Process::CLOCK_MONOTONIC) - started
  end

  after(:all) do
    FileUtils.rm_rf(@root) if @root
    if @seconds
      warn format("early cutoff corpus: %<builds>d builds in %<seconds>.1f s", builds: CutoffCorpus::CASES.size + 2,
                                                                               seconds: @seconds)
    end
  end

  # The produced files of +name+ at +version+ made of +tree+ (with its
  # debian/), built by the host backend, with the ABI dumps of its
  # libraries, as `relspec build` keeps them.
  def build(name, version, tree, build_depends: [], local: [])
    dir = File.join(@root, "#{name}-#{version}")
    tree.merge(CutoffCorpus.debian(name, version, build_depends: build_depends)).each do |path, content|
      FileUtils.mkdir_p(File.dirname(File.join(dir, "source", path)))
      File.write(File.join(dir, "source", path), content)
    end
    File.chmod(0o755, File.join(dir, "source", "debian", "rules"))
    output, status = Open3.capture2e("dpkg-source", "-b", "source", chdir: dir)
    raise "dpkg-source: #{output}" unless status.success?

    out = File.join(dir, "results")
    log = File.join(dir, "build.log")
    request = Relspec::Builder::Request.new(source: name, version: version, dsc: File.join(dir, "#{name}_#{version}.dsc"),
                                            target: Relspec::Target.new("bookworm", "amd64"), repositories: [],
                                            local_debs: local.grep(/\.deb\z/), output_dir: out, log: log)
    files = @backend.build(request)
    run = ->(command, log:) { @tool.run(name, command, log: log) }
    files + Relspec::Builder::AbiDumper.new(run).dump(files.grep(/\.deb\z/), out, log: log).map(&:path)
  rescue Relspec::Error => e
    raise "#{name} #{version}: #{e.message}\n#{File.read(log) if log && File.file?(log)}"
  end

  # A build's side, its .debs unpacked (for the headers) as relspec build does.
  def side(version, files)
    root = Dir.mktmpdir("side", @root)
    Relspec::Abi::InterfaceCheck::Side.of(version, files, root: root)
  end

  # What the two programs of the dependent print, installed (unpacked)
  # with the library built from +files+.
  def run_dependent(files)
    root = File.join(@root, "run-#{File.basename(File.dirname(files.first))}")
    (files + @user).grep(/\.deb\z/).reject { |deb| deb.include?("-dbgsym_") }.each do |deb|
      output, status = Open3.capture2e("dpkg-deb", "-x", deb, root)
      raise output unless status.success?
    end
    prefix = File.join(root, CutoffCorpus::PREFIX.delete_prefix("/"))
    %w[cut-user cut-userpp].map do |program|
      output, status = Open3.capture2e({ "LD_LIBRARY_PATH" => File.join(prefix, "lib") }, File.join(prefix, "bin", program))
      raise "#{program}: #{output}" unless status.success?

      output.chomp
    end
  end

  it "holds at least 20 changes that must rebuild the dependents and 5 that must not" do
    expect(CutoffCorpus::CASES.count(&:rebuild)).to be >= 20
    expect(CutoffCorpus::CASES.count { |corpus_case| !corpus_case.rebuild }).to be >= 5
  end

  it "keeps the dependents of the baseline rebuilt as it was: every file identical" do
    verdict = @check.decide("cutoff/lib", old: side("1.0", @base), new: side("1.0", @base))
    expect(verdict.unchanged?).to be(true)
    expect(verdict.evidence.map(&:path)).to include("opt/rock/cutoff/include/cut.h", "opt/rock/cutoff/lib/libcut.so.1.0")
    expect(run_dependent(@base)).to eq(CutoffCorpus::BASE_OUTPUT)
  end

  it "leaves a private type out only through the installed headers: without them abidiff names it changed" do
    _, files = @cases.fetch(CutoffCorpus::CASES.find { |corpus_case| corpus_case.name.start_with?("a private type") }.name)
    dump = ->(paths) { paths.find { |path| path.end_with?("libcut.so.1.0.abi.xml.gz") } }
    expect(Relspec::Abi::Comparison.compare(dump.call(@base), dump.call(files)).verdict).to eq("changed")
  end

  CutoffCorpus::CASES.each do |corpus_case|
    if corpus_case.rebuild
      it "rebuilds the dependents after #{corpus_case.name}" do
        verdict, = @cases.fetch(corpus_case.name)
        expect(verdict.unchanged?).to be(false), verdict.summary
        changed = verdict.changes.map { |item| item.path.delete_prefix("opt/rock/cutoff/") }
        expect(changed).to include(*corpus_case.changed), verdict.summary
        next unless corpus_case.abi

        library = verdict.changes.find { |item| item.check == :abi }
        expect(corpus_case.abi).to include(library&.outcome), verdict.summary
      end
    else
      it "keeps the dependents after #{corpus_case.name}, and the kept dependent runs against the new library" do
        verdict, files = @cases.fetch(corpus_case.name)
        expect(verdict.unchanged?).to be(true), verdict.summary
        expect(verdict.evidence.map(&:path)).to include("opt/rock/cutoff/include/cut.h", "opt/rock/cutoff/share/orogen/cut.tlb")
        expect(run_dependent(files)).to eq(corpus_case.runs)
      end
    end
  end
end
