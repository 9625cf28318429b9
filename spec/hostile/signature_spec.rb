# frozen_string_literal: true

require "spec_helper"

# Keyrings and signatures people get wrong (issue 12, case 9), through the
# real CLI: an ASCII-armored keyring (keys/*.asc) is accepted as gpg
# --export --armor writes it, and an empty Release.gpg is named as such.
RSpec.describe "relspec plan with armored keyrings and empty signatures" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-signature")
    @fixture = ReleaseFixture.new(@dir)
    @home = File.join(@dir, "gnupg")
    Dir.mkdir(@home, 0o700)
    gpg("--passphrase", "", "--quick-gen-key", "Test Repo <repo@example.org>", "ed25519", "sign", "never")
    FileUtils.mkdir_p(File.join(@dir, "keys"))
    File.binwrite(File.join(@dir, "keys", "repo.asc"), IO.popen({ "GNUPGHOME" => @home }, %w[gpg --export --armor], &:read))
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def gpg(*args)
    system({ "GNUPGHOME" => @home }, "gpg", "--batch", "--quiet", "--yes", *args, exception: true, err: File::NULL)
  end

  # A signed ancestor repository: InRelease, or Release + Release.gpg.
  def signed_repository(name, clearsigned:)
    path = @fixture.repository(name, [%w[bionic amd64]], { "base/cmake" => {} })
    dists = File.join(path, "dists", "bionic")
    FileUtils.rm_f(Dir.glob(File.join(dists, "{InRelease,Release.gpg}")))
    if clearsigned
      gpg("--clearsign", "--output", File.join(dists, "InRelease"), File.join(dists, "Release"))
    else
      gpg("--detach-sign", "--output", File.join(dists, "Release.gpg"), File.join(dists, "Release"))
    end
    dists
  end

  def plan_child_of(name)
    @fixture.spec(name, "targets: { bionic: [amd64] }\nrepository: { path: ../repos/#{name}, keyring: ../keys/repo.asc }\n")
    @fixture.spec("child-of-#{name}", "parent: #{name}\n")
    relspec("plan", "specs/child-of-#{name}.yml", chdir: @dir)
  end

  it "verifies InRelease and Release.gpg with an armored keyring" do
    signed_repository("clearsigned", clearsigned: true)
    run = plan_child_of("clearsigned")
    expect(run.exit_code).to eq(0), run.stderr
    signed_repository("detached", clearsigned: false)
    run = plan_child_of("detached")
    expect(run.exit_code).to eq(0), run.stderr
  end

  it "still refuses a bad signature with an armored keyring" do
    dists = signed_repository("tampered", clearsigned: true)
    in_release = File.join(dists, "InRelease")
    File.write(in_release, File.read(in_release).sub("Codename: bionic", "Codename: bionix"))
    run = plan_child_of("tampered")
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("InRelease: signature check failed: BAD signature")
  end

  it "says that an empty Release.gpg is empty" do
    dists = signed_repository("empty-signature", clearsigned: false)
    File.write(File.join(dists, "Release.gpg"), "")
    run = plan_child_of("empty-signature")
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("repos/empty-signature/dists/bionic/Release.gpg is empty: the repository must be signed again")
    expect(run.stderr).not_to match(/\.rb:\d+:in |Unknown system error/)
  end
end
