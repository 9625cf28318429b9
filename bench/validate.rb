# frozen_string_literal: true

# bench/validate: how long `relspec validate` takes on a spec hierarchy.
#
# Peer: a Ruby process that only parses the same files with Psych
# (YAML.safe_load_file), the floor any Ruby tool pays. Printed: median wall
# time of whole processes (startup included, as a user waits for them) and the
# ratio to the peer. Target (DESIGN §10): < 0.3 s.
#
#   bundle exec ruby bench/validate.rb [RUNS]

require "fileutils"
require "rbconfig"
require "tmpdir"
require_relative "timing"

ROOT = File.expand_path("..", __dir__)
RUNS = Integer(ARGV.fetch(0, "9"))

# Children start clean: no RUBYOPT inherited from `bundle exec`, so the peer
# does not pay for Bundler and relspec pays for it only because it asks.
ENVIRONMENT = { "RUBYOPT" => nil, "BUNDLE_GEMFILE" => File.join(ROOT, "Gemfile") }.freeze

def median_seconds(command, chdir:)
  Timing.median(RUNS) do
    system(ENVIRONMENT, *command, chdir: chdir, out: File::NULL, err: File::NULL) or raise "failed: #{command.join(' ')}"
  end
end

# A realistic large hierarchy: 3 levels, 4 targets, 400 pins and 100
# blacklist entries in the leaf.
def write_large_hierarchy(dir)
  specs = File.join(dir, "specs")
  FileUtils.mkdir_p(specs)
  File.write(File.join(specs, "big-root.yml"), <<~YAML)
    release: big-root
    targets: { bionic: [amd64, arm64], focal: [amd64], buster: [amd64] }
    maintainer: Bench <bench@example.org>
    repository: { path: /srv/big-root, trusted: true }
  YAML
  File.write(File.join(specs, "big-mid.yml"), "release: big-mid\nparent: big-root\n" \
                                              "pins:\n#{(0...200).map { |i| "  pkg/p#{i}: { tag: v#{i} }\n" }.join}")
  File.write(File.join(specs, "big-leaf.yml"), "release: big-leaf\nparent: big-mid\n" \
                                               "pins:\n#{(0...400).map { |i| "  pkg/p#{i}: { commit: #{format('%07x', i + 0xabc0000)} }\n" }.join}" \
                                               "blacklist:\n#{(0...100).map { |i| "  - { match: \"group#{i}/*\", reason: bench }\n" }.join}")
  specs
end

relspec = [RbConfig.ruby, "-rbundler/setup", File.join(ROOT, "exe", "relspec"), "validate"]
# As an installed gem runs: RubyGems activates the gems, no Bundler resolution.
relspec_gem = [RbConfig.ruby, File.join(ROOT, "exe", "relspec"), "validate"]
psych_peer = ->(files) { [RbConfig.ruby, "-ryaml", "-e", "ARGV.each { |f| YAML.safe_load_file(f) }", *files] }

rows = []
example_files = Dir.glob("specs/*.yml", base: ROOT).sort
rows << ["example (specs/, 2 files)", median_seconds(relspec, chdir: ROOT),
         median_seconds(psych_peer.call(example_files), chdir: ROOT), median_seconds(relspec_gem, chdir: ROOT)]
Dir.mktmpdir("relspec-bench") do |dir|
  write_large_hierarchy(dir)
  files = Dir.glob("specs/*.yml", base: dir).sort
  rows << ["generated (3 levels, 400 pins)", median_seconds(relspec, chdir: dir),
           median_seconds(psych_peer.call(files), chdir: dir), median_seconds(relspec_gem, chdir: dir)]
end

# The same work inside one process: what relspec itself costs once loaded.
$LOAD_PATH.unshift(File.join(ROOT, "lib"))
require "relspec"
def in_process_seconds(dir)
  Timing.median(RUNS) do
    library = Relspec::ReleaseSpec::Library.new(dir)
    library.paths.each { |path| Relspec::ReleaseSpec::Resolution.of(library, path) }
  end
end
rows[0] << in_process_seconds(File.join(ROOT, "specs"))
Dir.mktmpdir("relspec-bench") { |dir| rows[1] << in_process_seconds(write_large_hierarchy(dir)) }

puts format("%-32s %12s %12s %16s %8s %16s", "hierarchy", "bundled (s)", "gem (s)", "psych-only (s)", "ratio",
            "in-process (ms)")
rows.each do |name, ours, peer, gem, inside|
  puts format("%-32s %12.3f %12.3f %16.3f %7.2fx %16.1f", name, ours, gem, peer, gem / peer, inside * 1000)
end
puts "bundled: `relspec validate` process under Bundler (bundle exec); gem: the same without Bundler, as an " \
     "installed gem runs; psych-only: `ruby -ryaml` parsing the same files; ratio: gem / psych-only."
puts "target: relspec < 0.300 s per hierarchy (median of #{RUNS} runs, process startup included)"
