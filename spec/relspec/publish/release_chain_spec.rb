# frozen_string_literal: true

require "spec_helper"
require_relative "../../support/signing_key"
require "json"

# A base release published signed, and a child release that inherits from
# it through its signature: the child plans with the parent's `keyring:` (no
# `trusted: true`), builds only what it blacklists, is published next to it,
# and apt installs the child's package with the inherited dependency from the
# parent's repository. A Release file changed after signing is refused.
RSpec.describe "a signed release chain, published and inherited" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-chain")
    @gnupg = File.join(@dir, "gnupg")
    FileUtils.mkdir_p(@gnupg, mode: 0o700)
    @fingerprint = generate_key
    FileUtils.mkdir_p(File.join(@dir, "keys"))
    output, status = Open3.capture2e(gpg_env, "gpg", "--batch", "--output", File.join(@dir, "keys", "base.gpg"), "--export", @fingerprint)
    raise output unless status.success?

    @fixture = ReleaseFixture.new(@dir)
    @fixture.spec("base", <<~YAML, workspace: :checkouts)
      select: [base/logging]
      targets: { bookworm: [amd64] }
      maintainer: Demo <demo@example.org>
      repository: { path: ../repos/base, keyring: ../keys/base.gpg, sign_with: #{@fingerprint} }
    YAML
    @fixture.spec("child", <<~YAML, workspace: :checkouts)
      parent: base
      select: [base/logging]
      blacklist:
        - match: base/logging
          reason: the project needs its own logging
      repository: { path: ../repos/child, trusted: true }
    YAML
    run!("compile", "specs/base.yml", "--out", "out")
    run!("build", "specs/base.yml", "--out", "out", "--backend", "host")
    @published = run!("publish", "specs/base.yml", "--out", "out")
  end

  after(:all) do
    @signing_key&.stop
    FileUtils.rm_rf(@dir)
  end

  def gpg_env
    { "GNUPGHOME" => @gnupg }
  end

  def generate_key
    @signing_key = SigningKey.new(@gnupg)
    @signing_key.fingerprint
  end

  def run!(*args)
    run = relspec(*args, chdir: @dir, env: gpg_env)
    raise "relspec #{args.join(' ')}: #{run.stderr}" unless run.status.success?

    run
  end

  def decisions(run)
    JSON.parse(run.stdout).fetch("targets").fetch("bookworm/amd64").transform_values { |entry| entry["decision"] }
  end

  def base_repository
    File.join(@dir, "repos", "base")
  end

  it "signs the parent with sign_with; the child inherits, builds its blacklist, and apt installs it with the parent's key" do
    expect(File.read(File.join(base_repository, "conf", "distributions"))).to include("SignWith: #{@fingerprint}\n")
    in_release = File.join(base_repository, "dists", "bookworm", "InRelease")
    output, status = Open3.capture2e("gpgv", "--keyring", File.join(@dir, "keys", "base.gpg"), in_release)
    expect(status).to be_success, output

    plan = run!("plan", "specs/child.yml", "--format", "json")
    expect(decisions(plan)).to eq("base/cmake" => "inherit", "base/logging" => "build")

    run!("compile", "specs/child.yml", "--out", "out")
    expect(Dir.children(File.join(@dir, "out", "child", "bookworm-amd64")).sort)
      .to contain_exactly(@fixture.deb("child", "base/logging"), "plan.yml")
    # base/cmake, inherited, comes from base's repository
    run!("build", "specs/child.yml", "--out", "out", "--backend", "host")
    run!("publish", "specs/child.yml", "--out", "out")
    expect(File.read(File.join(@dir, "repos", "child", "osdeps", "child-amd64.yml"))).to eq(<<~YAML)
      ---
      base/cmake:
        debian:
          12,bookworm: #{@fixture.deb('base', 'base/cmake')}
      base/logging:
        debian:
          12,bookworm: #{@fixture.deb('child', 'base/logging')}
    YAML

    Dir.mktmpdir("relspec-apt") do |apt_dir|
      apt = PrivateApt.new(apt_dir, [PrivateApt.source(base_repository, "bookworm", keyring: File.join(@dir, "keys", "base.gpg")),
                                     PrivateApt.source(File.join(@dir, "repos", "child"), "bookworm")])
      output, status = apt.update
      expect(status).to be_success, output
      output, status = apt.simulate(@fixture.deb("child", "base/logging"))
      expect(status).to be_success, output
      expect(output).to include("Inst #{@fixture.deb('base', 'base/cmake')} ", "Inst #{@fixture.deb('child', 'base/logging')} ")
    end
  end

  it "refuses the parent's repository once its Release was changed after signing" do
    dists = File.join(base_repository, "dists", "bookworm")
    originals = %w[InRelease Release].to_h { |name| [name, File.read(File.join(dists, name))] }
    originals.each { |name, text| File.write(File.join(dists, name), text.sub("Label: base", "Label: evil")) }
    run = relspec("plan", "specs/child.yml", chdir: @dir)
    expect(run.exit_code).not_to eq(0)
    expect(run.stderr).to include("ancestor base", "InRelease: signature check failed: BAD signature")
    expect(run.stderr).not_to include(".rb:")
  ensure
    originals&.each { |name, text| File.write(File.join(dists, name), text) }
  end

  it "stops before including anything when the signing key is not in the keyring" do
    Dir.mktmpdir("gnupg", @dir) do |empty|
      run = relspec("publish", "specs/base.yml", "--out", "out", chdir: @dir, env: { "GNUPGHOME" => empty })
      expect(run.exit_code).to eq(1)
      expect(run.stderr).to include("gpg --list-secret-keys #{@fingerprint} failed (exit status 2)", "repository.sign_with")
    end
  end
end
