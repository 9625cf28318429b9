# frozen_string_literal: true

require "digest"
require "fileutils"
require "zlib"

# Turns one distribution of a reprepro repository (AptRepositoryBuilder)
# into a Debian archive caught in the middle of a mirror sync, as
# Debian's own trixie mirrors were when relspec first read them: its Release file
# says `Acquire-By-Hash: yes` and `No-Support-for-Architecture-all:
# Packages` (Architecture: all packages are in binary-<arch>), the
# by-hash/SHA256/<digest> files hold what the Release file lists, while the
# canonical binary-<arch> files and binary-all are still the old ones.
#
#   MidUpdateArchive.apply(repo, "trixie")                  # by-hash files right, canonical stale
#   MidUpdateArchive.apply(repo, "trixie", by_hash: false)  # canonical stale, no by-hash file at all
module MidUpdateArchive
  STALE = "Package: stale-only\nVersion: 0.1-1\nArchitecture: amd64\n" \
          "Maintainer: Test <test@example.org>\nDescription: what the index held before\n"
  ALL_LISTED = "Package: data-common\nVersion: 2-1\nArchitecture: all\n" \
               "Maintainer: Test <test@example.org>\nDescription: the binary-all the Release file lists\n"

  module_function

  # +by_hash+: whether the by-hash files are there (the Release file says
  # Acquire-By-Hash either way); +no_all+: whether it says
  # No-Support-for-Architecture-all: Packages.
  def apply(repository, codename, arch: "amd64", by_hash: true, no_all: true)
    dists = File.join(repository, "dists", codename)
    release = File.join(dists, "Release")
    listed = File.read(release).scan(%r{^ (\h{64}) +(\d+) (main/binary-#{arch}/Packages(?:\.gz|\.xz)?)$})
    raise "no SHA256 lines for binary-#{arch} in #{release}" if listed.empty?

    listed.each do |sha256, _, path|
      hash_file(dists, path, sha256, File.binread(File.join(dists, path))) if by_hash
      File.binwrite(File.join(dists, path), path.end_with?(".gz") ? Zlib.gzip(STALE) : STALE)
    end
    File.write(release, header(File.read(release), no_all) + all_lines(dists))
  end

  def hash_file(dists, path, sha256, bytes)
    folder = File.join(dists, File.dirname(path), "by-hash", "SHA256")
    FileUtils.mkdir_p(folder)
    File.binwrite(File.join(folder, sha256), bytes)
  end

  def header(text, no_all)
    fields = "Acquire-By-Hash: yes\n"
    fields += "No-Support-for-Architecture-all: Packages\n" if no_all
    text.sub(/^Architectures: /, "Architectures: all ").sub(/^MD5Sum:$/, "#{fields}MD5Sum:")
  end

  # binary-all as the Release file lists it (ALL_LISTED), while the file
  # served under that name, and by its hash, is the stale one.
  def all_lines(dists)
    folder = File.join(dists, "main", "binary-all")
    FileUtils.mkdir_p(folder)
    File.binwrite(File.join(folder, "Packages"), STALE)
    hash_file(dists, "main/binary-all/Packages", Digest::SHA256.hexdigest(ALL_LISTED), STALE)
    " #{Digest::SHA256.hexdigest(ALL_LISTED)} #{ALL_LISTED.bytesize} main/binary-all/Packages\n"
  end
end
