# frozen_string_literal: true

# bench/index: parsing Debian bookworm main amd64 Packages (about 63k stanzas)
# with relspec's reader next to python3-apt's apt_pkg.TagFile, in one run.
#
#   bundle exec ruby bench/index.rb [PACKAGES_FILE]
#
# Without an argument, the file comes from this machine's apt lists (run
# `apt-get update` first; they are lz4-compressed). Needs python3-apt.
# Targets (issue 4): ≤ 1.0× apt_pkg for the fields the planner needs,
# ≤ 2× for a full parse.
require "open3"
require "tmpdir"
require_relative "timing"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/apt/packages_scanner"
require "relspec/apt/package_index"
require "relspec/apt/deb822"

RUNS = 5
FIELDS = %w[Package Version Depends Provides Source].freeze

def packages_file(dir)
  return ARGV[0] if ARGV[0]

  list = Dir.glob("/var/lib/apt/lists/*_debian_dists_bookworm_main_binary-amd64_Packages*").first
  abort "no bookworm Packages in /var/lib/apt/lists: run apt-get update" unless list
  path = File.join(dir, "Packages")
  system("lz4cat #{list} > #{path}", exception: true) if list.end_with?(".lz4")
  list.end_with?(".lz4") ? path : list
end

PYTHON = <<~PY
  import apt_pkg, sys, time
  mode, path, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
  fields = ["Package", "Version", "Depends", "Provides", "Source"]
  times = []
  for _ in range(runs):
      start = time.perf_counter()
      with apt_pkg.TagFile(path) as tagfile:
          for section in tagfile:
              if mode == "fields":
                  for field in fields:
                      section.get(field)
              else:
                  for key in section.keys():
                      section[key]
      times.append(time.perf_counter() - start)
  print(sorted(times)[runs // 2])
PY

def python_seconds(mode, path)
  out, status = Open3.capture2("/usr/bin/python3", "-c", PYTHON, mode, path, RUNS.to_s)
  abort "python3-apt failed (install python3-apt)" unless status.success?
  Float(out)
end

def ruby_seconds(&)
  Timing.median(RUNS, &)
end

Dir.mktmpdir("relspec-bench-index") do |dir|
  path = packages_file(dir)
  text = File.binread(path)
  stanzas = text.scan(/^Package: /).size
  fields = ruby_seconds { Relspec::Apt::PackagesScanner.new(text).each(FIELDS) { |_stanza| nil } }
  index = ruby_seconds { Relspec::Apt::PackageIndex.parse(text) }
  full = ruby_seconds { Relspec::Apt::Deb822.each(text) { |_fields, _line| nil } }
  peer_fields = python_seconds("fields", path)
  peer_full = python_seconds("full", path)
  puts "#{path}: #{stanzas} stanzas, #{(text.bytesize / 1e6).round(1)} MB (read once, not timed)"
  puts format("%-40s %10s %12s %8s", "work", "relspec", "apt_pkg", "ratio")
  puts format("%-40s %9.3fs %11.3fs %7.2fx", "planner fields (Package Version Depends …)", fields, peer_fields, fields / peer_fields)
  puts format("%-40s %9.3fs %11.3fs %7.2fx", "PackageIndex (fields + newest per name)", index, peer_fields, index / peer_fields)
  puts format("%-40s %9.3fs %11.3fs %7.2fx", "full read (every field of every stanza)", full, peer_full, full / peer_full)
  puts "median of #{RUNS} runs each; targets: fields ≤ 1.0x, full ≤ 2.0x (C reader #{Relspec::Apt::NativeReader.available? ? 'compiled' : 'NOT compiled: pure Ruby'})"
end
