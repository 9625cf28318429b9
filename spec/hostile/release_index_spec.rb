# frozen_string_literal: true

require "spec_helper"

# Releases the package set's release index (releases.yml) cannot express,
# through the real CLI: each is refused with the spec's file:line, exit 1,
# and no releases.yml is written. The package set builds apt lines as
# <repo_url>/<release>: a missing URL gave `deb [...] /demo-base bookworm main`,
# which makes every apt command on the user's machine fail (issue 23).
RSpec.describe "relspec osdeps index and package-set on releases the index cannot express", :tmpdir do
  def refused(command, specs, *args)
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    specs.each { |name, text| File.write(File.join(@dir, "specs", "#{name}.yml"), "release: #{name}\n#{text}") }
    run = relspec("osdeps", command, *args, chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
    expect(File.exist?(File.join(@dir, "releases", "releases.yml"))).to be(false)
    expect(Dir.exist?(File.join(@dir, "build"))).to be(false)
    run.stderr
  end

  def index(specs, *args)
    refused("index", specs, *args)
  end

  TARGETS = "targets: { bookworm: [amd64] }\n"

  it "refuses a release without a repository URL" do
    expect(index("a" => TARGETS)).to start_with(
      "specs/a.yml:1:1: error[index-url]: the release has no repository.url: the release index needs where users' apt reads a\n"
    )
  end

  it "refuses a repository URL that is not http(s)" do
    expect(index("a" => "#{TARGETS}repository:\n  url: file:///srv/a\n"))
      .to start_with("specs/a.yml:3:1: error[index-url]: the repository URL \"file:///srv/a\" is not an http(s) URL")
  end

  it "refuses a repository URL whose last segment is not the release name" do
    expect(index("a" => "#{TARGETS}repository: { url: https://example.org/releases/b }\n")).to start_with(
      "specs/a.yml:3:1: error[index-url]: the repository URL \"https://example.org/releases/b\" does not end in " \
      "the release name \"a\": the index can only say <repo_url>/a\n"
    )
  end

  it "refuses a release with several parents" do
    specs = { "a" => "#{TARGETS}repository: { url: https://example.org/r/a }\n",
              "b" => "#{TARGETS}repository: { url: https://example.org/r/b }\n",
              "c" => "parent: [a, b]\nrepository: { url: https://example.org/r/c }\n" }
    expect(index(specs)).to eq(
      "specs/c.yml:2:1: error[index-parents]: c has 2 parents; the release index holds one (depends_on)\n1 error in 1 file\n"
    )
  end

  it "refuses an external parent" do
    specs = { "c" => "parent: x\nexternal: { x: { url: https://example.org/r/x, targets: { bookworm: [amd64] } } }\n" \
                     "repository: { url: https://example.org/r/c }\n" }
    expect(index(specs)).to eq("specs/c.yml:2:1: error[index-parents]: the parent x has no spec here; the release " \
                               "index cannot point to an external release\n1 error in 1 file\n")
  end

  it "refuses an install prefix other than /opt/rock" do
    expect(index("a" => "#{TARGETS}repository: { url: https://example.org/r/a }\ninstall_prefix: /opt/other\n")).to eq(
      "specs/a.yml:4:1: error[index-prefix]: install_prefix /opt/other cannot be expressed in the release index: " \
      "package sets find packages' env.yml below /opt/rock\n1 error in 1 file\n"
    )
  end

  it "refuses a --repo-url that is not http(s)" do
    expect(index({ "a" => "#{TARGETS}repository: { url: https://example.org/r/a }\n" }, "--repo-url", "/srv"))
      .to eq("relspec: error: --repo-url must be an http(s) URL, not \"/srv\"\n")
  end

  it "writes no package set for a release the index cannot express" do
    expect(refused("package-set", "a" => "#{TARGETS}repository: { url: https://example.org/r/b, path: ../repo, trusted: true }\n"))
      .to start_with("specs/a.yml:3:1: error[index-url]: the repository URL \"https://example.org/r/b\" does not end in")
  end

  it "refuses a package set for a release without a repository path" do
    expect(refused("package-set", "a" => "#{TARGETS}repository: { url: https://example.org/r/a, trusted: true }\n")).to eq(
      "specs/a.yml:3:1: error[package-set-repository]: a has no repository.path: the package set is made from the " \
      "published repository\n1 error in 1 file\n"
    )
  end

  it "refuses a package set for a repository apt could not verify" do
    expect(refused("package-set", "a" => "#{TARGETS}repository: { url: https://example.org/r/a, path: ../repo }\n")).to eq(
      "specs/a.yml:3:1: error[package-set-trust]: a's repository has neither a public keyring (repository.keyring) nor " \
      "trusted: true: apt would refuse it\n1 error in 1 file\n"
    )
  end

  it "refuses a package set for a release not published for one of its targets" do
    expect(refused("package-set", "a" => "#{TARGETS}repository: { url: https://example.org/r/a, path: ../repo, trusted: true }\n"))
      .to eq("specs/a.yml:3:1: error[package-set-unpublished]: a is not published for bookworm/amd64 in repo\n" \
             "  hint: run `relspec publish` for it first\n1 error in 1 file\n")
  end
end
