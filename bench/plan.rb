# frozen_string_literal: true

# bench/plan: planning a generated release of N packages × 4 targets × 3
# ancestors, indices on disk (as cached), for N = 400, 1500, 5000.
#
# The ancestors' repositories are written directly in apt's format
# (dists/<codename>/Release with SHA256 lines, main/binary-<arch>/Packages.gz),
# without .deb files: the planner reads only indices. The catalog is a
# snapshot. Printed: in-process Plan.run wall and CPU time (median), the
# time per package and its growth against the first size, and index reads
# per plan. Targets: < 1 s at 400, per-package growth <= 1.3x (issue 22).
#
#   bundle exec ruby bench/plan.rb [SIZES] [RUNS]
require "digest"
require "fileutils"
require "tmpdir"
require_relative "timing"
require "zlib"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/plan"
require "relspec/catalog/snapshot_source"

SIZES = ARGV.fetch(0, "400,1500,5000").split(",").map { |size| Integer(size) }
RUNS = Integer(ARGV.fetch(1, "5"))
TARGETS = [%w[bionic amd64], %w[bionic arm64], %w[buster amd64], %w[buster arm64]].freeze
ANCESTORS = %w[gen-a gen-b gen-c].freeze # gen-a is the nearest

def catalog(count)
  packages = Array.new(count) do |i|
    dependencies = [i - 1, i / 2, i / 3].uniq.select { |d| d >= 0 && d < i }.map { |d| "pkg/p#{d}" }
    Relspec::Catalog::Package.new(
      name: "pkg/p#{i}", package_set: "bench", build_type: i % 10 == 9 ? "ruby" : "cmake",
      vcs: Relspec::Catalog::Vcs.new(type: "git", url: "https://example.org/p#{i}.git", commit: Digest::SHA1.hexdigest(i.to_s)),
      commit_time: "2020-06-01T00:00:00Z", source_dir: "src/pkg/p#{i}", version: "1.0", dependencies: dependencies
    )
  end
  Relspec::Catalog.new(packages: packages.to_h { |p| [p.name, p] }, layout: packages.map(&:name), codenames: %w[bionic buster])
end

def write_repository(dir, release, catalog)
  TARGETS.group_by(&:first).each do |codename, targets|
    lines = []
    targets.each do |_, arch|
      stanzas = catalog.packages.values.each_with_index.filter_map do |(package, _), i|
        next if (i + ANCESTORS.index(release)) % 3 == 1 # each ancestor lacks a third, so all are searched

        name = Relspec::Debian::Naming.deb_name(prefix: "rock", release: release, package_name: package.name,
                                                build_type: package.build_type)
        "Package: #{name}\nVersion: 1.0.20200601.000000-1~#{codename}\nArchitecture: #{arch}\n" \
          "Depends: libc6 (>= 2.27)\nDescription: #{package.name}\n"
      end
      gz = Zlib.gzip(stanzas.join("\n"))
      path = "main/binary-#{arch}/Packages.gz"
      FileUtils.mkdir_p(File.join(dir, "dists", codename, File.dirname(path)))
      File.binwrite(File.join(dir, "dists", codename, path), gz)
      lines << " #{Digest::SHA256.hexdigest(gz)} #{gz.bytesize} #{path}"
    end
    File.write(File.join(dir, "dists", codename, "Release"),
               "Codename: #{codename}\nArchitectures: amd64 arm64\nComponents: main\nSHA256:\n#{lines.join("\n")}\n")
  end
end

def setup(dir, count)
  catalog = catalog(count)
  File.write(File.join(dir, "catalog.yml"), Relspec::Catalog::SnapshotSource.dump(catalog))
  specs = File.join(dir, "specs")
  FileUtils.mkdir_p(specs)
  ANCESTORS.each_with_index do |release, i|
    write_repository(File.join(dir, "repos", release), release, catalog)
    parent = ANCESTORS[i + 1] ? "parent: #{ANCESTORS[i + 1]}\n" : ""
    File.write(File.join(specs, "#{release}.yml"), "release: #{release}\n#{parent}workspace: ../catalog.yml\n" \
                                                   "targets: { bionic: [amd64, arm64], buster: [amd64, arm64] }\n" \
                                                   "repository: { path: ../repos/#{release}, trusted: true }\n")
  end
  File.write(File.join(specs, "gen-leaf.yml"), "release: gen-leaf\nparent: gen-a\nworkspace: ../catalog.yml\n" \
                                               "blacklist: [{ match: pkg/p#{count / 2}, reason: bench }]\n")
  File.join(specs, "gen-leaf.yml")
end

# Per-package time at each size against the first size (the peer): 1.00x is
# linear growth. CPU time is printed too, because a shared machine's wall
# time moves with the other jobs; the growth ratio is taken from it.
puts format("%-9s %10s %10s %13s %13s %10s %10s", "packages", "wall (s)", "cpu (s)", "wall/package", "cpu/package",
            "growth", "decisions")
base = nil
growths = []
SIZES.each do |count|
  Dir.mktmpdir("relspec-bench-plan") do |dir|
    spec = setup(dir, count)
    result = nil
    runs = Array.new(RUNS) do
      cpu = Process.clock_gettime(Process::CLOCK_PROCESS_CPUTIME_ID)
      wall = Timing.seconds { result = Relspec::Plan.run(spec, cache_dir: nil) }
      [wall, Process.clock_gettime(Process::CLOCK_PROCESS_CPUTIME_ID) - cpu]
    end
    wall = runs.map(&:first).sort[RUNS / 2]
    cpu = runs.map(&:last).sort[RUNS / 2]
    base ||= cpu / count
    growth = (cpu / count) / base
    growths << growth
    decisions = result.plan.targets.values.sum(&:size)
    puts format("%-9d %10.3f %10.3f %11.2fms %11.2fms %9.2fx %10d", count, wall, cpu, wall / count * 1000,
                cpu / count * 1000, growth, decisions)
  end
end
puts format("per-package growth across sizes (cpu): %.2fx (target: <= 1.3x)", growths.max)
puts "index reads per plan: 3 ancestors x 4 targets = 12 Packages files and 6 Release files, whatever the size"
