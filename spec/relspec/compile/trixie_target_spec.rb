# frozen_string_literal: true

require "spec_helper"
require "open3"
require "yaml"

# Debian 13 trixie as a built-in target: a spec that names it without a
# `distributions:` entry validates, plans and compiles, and everything that
# depends on the codename is trixie's own beside bookworm's in the same
# release (version suffix, debhelper compat, the package set's osdeps entry
# for trixie, the Ruby folders on RUBYLIB, the osdeps file's keys).
RSpec.describe "a release for trixie and bookworm" do
  before(:all) do
    @base = Dir.mktmpdir("relspec-trixie")
    builder = WorkspaceBuilder.new(@base)
    builder.package("base/app", type: :cmake, date: "2020-06-02T10:00:00Z", osdeps: %w[libx ruby])
    builder.osdeps(<<~YAML)
      libx:
        debian:
          bookworm: libx-bookworm-dev
          trixie: libx-trixie-dev
          default: libx-old-dev
    YAML
    builder.create
    # what autoproj loads for the target's Ruby: `ruby` is ruby33 on trixie
    sets = File.join(builder.root, "package_sets", builder.package_set_name)
    { "31" => "ruby3.1-dev", "33" => "ruby3.3-dev" }.each do |version, name|
      File.write(File.join(sets, "#{builder.package_set_name}.osdeps-ruby#{version}"), "ruby#{version}:\n  debian: #{name}\n")
    end
    FileUtils.mkdir_p(File.join(@base, "specs"))
    File.write(File.join(@base, "specs", "two.yml"), <<~YAML)
      release: two
      maintainer: Rock Packaging <rock@example.org>
      workspace: ../workspace
      select: [base/app]
      targets: { bookworm: [amd64], trixie: [amd64] }
    YAML
    @validate = relspec("validate", "specs/two.yml", chdir: @base)
    @plan = relspec("plan", "specs/two.yml", chdir: @base)
    @compile = relspec("compile", "specs/two.yml", "--out", "out", chdir: @base)
  end

  after(:all) { FileUtils.rm_rf(@base) if @base }

  def source_file(codename, ending)
    Dir.glob(File.join(@base, "out", "two", "#{codename}-amd64", "rock-two-base-app", "*#{ending}")).first
  end

  # Every file of the package's debian/, as one text.
  def debian_text(codename)
    text, status = Open3.capture2("tar", "-xJOf", source_file(codename, ".debian.tar.xz"), "--wildcards", "debian/*")
    raise "no debian/ for #{codename}" unless status.success?

    text
  end

  it "validates, plans and compiles without a distributions: entry" do
    [@validate, @plan, @compile].each { |run| expect(run.exit_code).to eq(0), "#{run.args.first}: #{run.stderr}" }
    expect(@plan.stdout).to include("trixie/amd64")
  end

  it "gives each target its own version suffix, debhelper compat, osdeps entry and Ruby's osdeps" do
    { "bookworm" => "3.1", "trixie" => "3.3" }.each do |codename, ruby|
      dsc = File.read(source_file(codename, ".dsc"))
      expect(dsc).to match(/^Version: \S+-1~#{codename}$/)
      build_depends = dsc[/^Build-Depends: (.*)$/, 1]
      expect(build_depends).to include("debhelper-compat (= 13)", "libx-#{codename}-dev", "ruby#{ruby}-dev")
      expect(build_depends).not_to include("libx-old-dev")
      expect(build_depends.scan(/ruby\d\.\d-dev/)).to eq(["ruby#{ruby}-dev"])
    end
  end

  it "puts the target Ruby's folders on RUBYLIB: 3.3 on trixie, 3.1 on bookworm" do
    { "trixie" => "3.3.0", "bookworm" => "3.1.0" }.each do |codename, abi|
      expect(debian_text(codename)).to include("lib/ruby/#{abi}", "lib/x86_64-linux-gnu/ruby/#{abi}")
    end
  end

  it "writes the osdeps file keyed by the labels autoproj gives Debian 13" do
    osdeps = YAML.safe_load_file(File.join(@base, "releases", "two", "osdeps", "two-amd64.yml"))
    expect(osdeps.fetch("base/app")).to eq("debian" => { "12,bookworm" => "rock-two-base-app",
                                                         "13,trixie" => "rock-two-base-app" })
  end
end
