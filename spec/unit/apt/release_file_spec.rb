# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/apt/release_file"

# How apt reads an archive's indices, from its Release file alone.
RSpec.describe Relspec::Apt::ReleaseFile do
  def release(fields, all: true)
    listed_all = all ? " #{'b' * 64} 10 main/binary-all/Packages.xz\n" : ""
    described_class.parse("Codename: trixie\n#{fields}SHA256:\n #{'a' * 64} 10 main/binary-amd64/Packages\n " \
                          "../../etc/passwd 10 main/binary-arm64/Packages\n#{listed_all}")
  end

  it "reads binary-all beside binary-<arch> only where the archive lists one and does not say its packages are elsewhere" do
    expect(release("Architectures: all amd64\nNo-Support-for-Architecture-all: Packages\n").package_architectures("amd64"))
      .to eq(["amd64"])
    expect(release("Architectures: all amd64\n").package_architectures("amd64")).to eq(%w[amd64 all])
    expect(release("Architectures: all amd64\n", all: false).package_architectures("amd64")).to eq(["amd64"])
    expect(release("Architectures: all amd64\n").package_architectures("amd64", component: "contrib")).to eq(["amd64"])
    expect(release("Architectures: amd64\n").package_architectures("amd64")).to eq(["amd64"])
    expect(release("").package_architectures("amd64")).to eq(%w[amd64 all])
    expect(release("Architectures: all amd64\n").package_architectures("all")).to eq(["all"])
    # another index kind without binary-all leaves Packages' alone
    expect(release("Architectures: all amd64\nNo-Support-for-Architecture-all: Contents\n").package_architectures("amd64"))
      .to eq(%w[amd64 all])
  end

  it "says Acquire-By-Hash with apt's words for yes" do
    expect(%w[yes Yes true 1].map { |word| release("Acquire-By-Hash: #{word}\n").by_hash? }).to eq([true] * 4)
    expect(["Acquire-By-Hash: no\n", ""].map { |fields| release(fields).by_hash? }).to eq([false, false])
  end

  it "takes a listed SHA256 for one only when it is 64 lowercase hex digits" do
    file = release("")
    expect(file.checksum("main/binary-amd64/Packages")).to be_valid
    expect(file.checksum("main/binary-arm64/Packages")).not_to be_valid
    expect(described_class::Checksum.new("A" * 64, 1)).not_to be_valid
  end
end
