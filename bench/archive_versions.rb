# frozen_string_literal: true

# The archive-versions entry (Plan::ArchiveVersions) of this machine's
# bookworm main list: the checked load against its peer, the same entry
# split without any check (what relspec did before issue 34), and against
# parsing the index itself (what the entry saves).
#
#   bundle exec ruby -Ilib bench/archive_versions.rb [RUNS]
require "digest"
require "relspec/apt/host_lists"
require "relspec/plan/archive_versions"

runs = Integer(ARGV.fetch(0, "5"))
clock = -> { Process.clock_gettime(Process::CLOCK_MONOTONIC) }
arch = `dpkg --print-architecture`.strip
started = clock.call
versions = Relspec::Plan::ArchiveVersions.from_index(Relspec::Apt::HostLists.new.packages("bookworm", arch))
parse = clock.call - started
dump = versions.dump

started = clock.call
runs.times { Relspec::Plan::ArchiveVersions.load(dump) }
checked = (clock.call - started) / runs

started = clock.call
runs.times do
  sha256, body = dump.split("\n", 2)
  Digest::SHA256.hexdigest(body) == sha256 or raise "entry changed"
  packages, provided = body.split("#{Relspec::Plan::ArchiveVersions::SEPARATOR}\n", 2)
  packages.split("\n").to_h { |line| line.split(" ", 2) }
  provided.split("\n").map { |line| line.split(" ", 2) }
end
unchecked = (clock.call - started) / runs

printf("%d names, entry %.1f MB; checked load %.3f s, unchecked peer %.3f s: ratio %.2f; parsing the index %.2f s\n",
       versions.names.size, dump.bytesize / 1e6, checked, unchecked, checked / unchecked, parse)
