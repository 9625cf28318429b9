# frozen_string_literal: true

require_relative "../unit_helper"
require "digest"
require "zlib"
require "relspec/target"
require "relspec/mirror/apt_repository"
require "relspec/mirror/integrity"

# A mirror's folder written here as reprepro lays it out (no reprepro):
# one index in two forms, its Release file, the pool file it names.
RSpec.describe Relspec::Mirror::Integrity, :tmpdir do
  let(:target) { Relspec::Target.parse("bookworm/amd64") }
  let(:deb) { "pool/main/a/aa/aa_1.0_amd64.deb" }

  def stanza(name, file)
    "Package: #{name}\nVersion: 1.0\nArchitecture: amd64\nFilename: #{file}\nSize: 3\n" \
      "SHA256: #{Digest::SHA256.hexdigest('deb')}\n"
  end

  def write_mirror(gz_text: nil)
    text = stanza("aa", deb)
    files = { "main/binary-amd64/Packages" => text, "main/binary-amd64/Packages.gz" => Zlib.gzip(gz_text || text) }
    files.each { |path, bytes| write("dists/bookworm/#{path}", bytes) }
    write("dists/bookworm/Release", "Codename: bookworm\nArchitectures: amd64\nComponents: main\nSHA256:\n" +
                                    files.map { |path, bytes| " #{Digest::SHA256.hexdigest(bytes)} #{bytes.bytesize} #{path}\n" }.join)
    write(deb, "deb")
  end

  def write(path, bytes)
    FileUtils.mkdir_p(File.dirname(File.join(@dir, path)))
    File.binwrite(File.join(@dir, path), bytes)
  end

  def check
    described_class.new(Relspec::Mirror::AptRepository.new(@dir, targets: [target]), [target], key: nil).check
  end

  it "passes a mirror whose files are what its Release file and index say" do
    write_mirror
    expect(check.to_h).to eq(name: "files", status: "passed", problems: [],
                             detail: "2 index files checked against their Release file (size, SHA256), 1 pool files against the indices")
  end

  it "names, from the mirror's own folder, each file that differs from what the others say" do
    write_mirror(gz_text: "")
    write("dists/bookworm/main/binary-amd64/Packages", stanza("aa", deb) + "\n" + stanza("bb", "pool/b.deb"))
    write("dists/bookworm/main/binary-amd64/Packages.xz", "")
    write("pool/main/z/zz/zz_1.0_amd64.deb", "zz")
    write("dists/sid/Release", "")
    expect(check.problems).to eq(["dists/bookworm/main/binary-amd64/Packages is larger than #{stanza('aa', deb).bytesize} " \
                                  "bytes, the most this file can hold",
                                  "dists/bookworm/main/binary-amd64/Packages.xz is not listed in the Release file",
                                  "dists/sid is the distribution of no target of mirror.yml",
                                  "pool/main/z/zz/zz_1.0_amd64.deb is in the pool but no index names it"])
    expect(check.status).to eq("failed")
  end

  it "finds forms of one index that hold different packages, each matching the Release file" do
    write_mirror(gz_text: stanza("aa", deb) + "\n" + stanza("cc", "pool/c.deb"))
    expect(check.problems).to eq(["dists/bookworm/main/binary-amd64/Packages.gz does not hold the packages of Packages (with cc)"])
  end

  it "says so when a target's Release file is missing" do
    write(deb, "deb")
    FileUtils.mkdir_p(File.join(@dir, "dists"))
    expect(check.problems.first).to include("has no distribution bookworm")
  end
end
