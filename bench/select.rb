# frozen_string_literal: true

# bench/select: the user-side blacklist selection over a generated release
# of 400 packages, relspec (in memory, from the Packages index) next to the
# per-package `apt-cache rdepends --recurse` approach on the same data, in
# the same run. apt is pointed at the generated repository with a private
# configuration (nothing of the machine's apt state is used or changed).
# Target: < 50 ms for relspec.
#
#   bundle exec ruby bench/select.rb [PACKAGES] [BLACKLISTED] [RUNS]
require "digest"
require "fileutils"
require "open3"
require "tmpdir"
require_relative "timing"
require "zlib"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/apt/package_index"
require "relspec/osdeps/selection"
require "relspec/osdeps/blacklist_file"
require "relspec/release_specs/package_pattern"

COUNT = Integer(ARGV.fetch(0, "400"))
BLACKLISTED = Integer(ARGV.fetch(1, "5"))
RUNS = Integer(ARGV.fetch(2, "5"))

def deb(i) = "rock-bench-pkg-p#{i}"

def write_repository(dir)
  stanzas = Array.new(COUNT) do |i|
    depends = [i / 2, i / 3, i / 5].uniq.select { |d| d.positive? && d < i }.map { |d| deb(d) } + ["libc6 (>= 2.27)"]
    "Package: #{deb(i)}\nVersion: 1.0-1~bionic\nArchitecture: amd64\nMaintainer: Bench <b@example.org>\n" \
      "Filename: pool/main/#{deb(i)}.deb\nSize: 1000\nDepends: #{depends.join(', ')}\nDescription: p#{i}\n"
  end
  text = stanzas.join("\n")
  index = File.join(dir, "repo", "dists", "bionic", "main", "binary-amd64")
  FileUtils.mkdir_p(index)
  File.write(File.join(index, "Packages"), text)
  gz = Zlib.gzip(text)
  File.binwrite(File.join(index, "Packages.gz"), gz)
  File.write(File.join(dir, "repo", "dists", "bionic", "Release"),
             "Codename: bionic\nArchitectures: amd64\nComponents: main\nSHA256:\n " \
             "#{Digest::SHA256.hexdigest(text)} #{text.bytesize} main/binary-amd64/Packages\n " \
             "#{Digest::SHA256.hexdigest(gz)} #{gz.bytesize} main/binary-amd64/Packages.gz\n")
  File.join(index, "Packages.gz")
end

# A private apt: its own sources, lists, cache and (empty) status file.
def apt_options(dir)
  apt = File.join(dir, "apt")
  %w[lists/partial cache/archives/partial etc/apt.conf.d etc/preferences.d].each { |d| FileUtils.mkdir_p(File.join(apt, d)) }
  File.write(File.join(apt, "status"), "")
  File.write(File.join(apt, "sources.list"), "deb [trusted=yes] file://#{dir}/repo bionic main\n")
  ["-o", "Dir::State::Lists=#{apt}/lists", "-o", "Dir::State::status=#{apt}/status", "-o", "Dir::Cache=#{apt}/cache",
   "-o", "Dir::Etc::SourceList=#{apt}/sources.list", "-o", "Dir::Etc::SourceParts=#{apt}/etc/none",
   "-o", "Dir::Etc::Parts=#{apt}/etc/apt.conf.d", "-o", "Dir::Etc::Preferences=#{apt}/etc/preferences",
   "-o", "Dir::Etc::PreferencesParts=#{apt}/etc/preferences.d", "-o", "Debug::NoLocking=1",
   "-o", "APT::Architecture=amd64", "-o", "APT::Architectures::=amd64"]
end

Dir.mktmpdir("relspec-bench-select") do |dir|
  packages_gz = write_repository(dir)
  options = apt_options(dir)
  out, status = Open3.capture2e("apt-get", *options, "update")
  abort "apt-get update on the private configuration failed:\n#{out}" unless status.success?

  mapping = Array.new(COUNT) { |i| ["pkg/p#{i}", deb(i)] }.to_h
  blacklisted = Array.new(BLACKLISTED) { |i| 20 + (i * 17) } # low in the graph: many reverse dependencies
  entries = blacklisted.map { |i| Relspec::Osdeps::BlacklistFile::Entry.new(Relspec::ReleaseSpec::PackagePattern.parse("pkg/p#{i}"), "bench") }

  ours = nil
  relspec = Timing.median(RUNS) do
    index = Relspec::Apt::PackageIndex.parse(Zlib.gunzip(File.binread(packages_gz)))
    ours = Relspec::Osdeps::Selection.new(mapping, [index], entries)
  end

  theirs = nil
  peer = Timing.median(RUNS) do
    theirs = blacklisted.flat_map do |i|
      output, = Open3.capture2("apt-cache", *options, "rdepends", "--recurse", deb(i))
      output.lines.map(&:strip).grep(/\Arock-/)
    end.uniq
  end

  disabled = ours.inactive.size
  puts "#{COUNT} packages, #{BLACKLISTED} blacklisted low-level packages, #{disabled} disabled in all"
  puts format("%-44s %10.1f ms", "relspec (parse index + selection, in memory)", relspec * 1000)
  puts format("%-44s %10.1f ms", "apt-cache rdepends --recurse, per package", peer * 1000)
  puts format("ratio relspec / apt-cache: %.3f; target < 50 ms", relspec / peer)
  puts "same packages disabled: #{theirs.sort == ours.inactive.keys.map { |p| mapping[p] }.sort}"
end
