# frozen_string_literal: true

# bench/abi: what `relspec abi` pays per library (abidiff of the two stored
# .abi.xml.gz dumps, unpacked, in relspec's Abi::Comparison) against the
# peer, `abidiff` of the two shared libraries themselves with their split
# debug information (what a reviewer without stored dumps runs). One run
# each (the issue asks for one), on a generated C++ library of CLASSES
# classes (each with 8 exported methods and a struct passed by reference),
# built twice with g++ -g -O2 as dh builds it and split as dh_strip splits
# it (debug file under .build-id/); the second build adds a data member to
# every 10th struct and one function. Also printed: the one-time cost of the
# dumps (abidw, paid once per build), and the library's size and symbols.
#
#   bundle exec ruby bench/abi.rb [CLASSES]
require "fileutils"
require "open3"
require "tmpdir"
require_relative "timing"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/builder/abi_dumper"
require "relspec/abi/comparison"

CLASSES = Integer(ARGV.fetch(0, "400"))

def run!(*command, chdir: nil)
  output, status = Open3.capture2e(*command, **(chdir ? { chdir: chdir } : {}))
  raise "#{command.join(' ')} failed: #{output}" unless status.success?

  output
end

def source(version)
  (0...CLASSES).map do |index|
    extra = version == 2 && (index % 10).zero? ? "  long added;\n" : ""
    methods = (0...8).map { |m| "  int m#{m}(const Data#{index}& d) const;\n" }.join
    bodies = (0...8).map { |m| "int Api#{index}::m#{m}(const Data#{index}& d) const { return d.a + #{m} + d.b; }\n" }.join
    "struct Data#{index} {\n  int a;\n#{extra}  double b;\n};\nclass Api#{index} {\npublic:\n#{methods}};\n#{bodies}"
  end.join + (version == 2 ? "int added_function() { return 2; }\n" : "")
end

# A library as a Debian build leaves it: stripped, its debug information
# in <dir>/debug/.build-id/xx/yyyy.debug.
def build(dir, version)
  FileUtils.mkdir_p(dir)
  File.write(File.join(dir, "lib.cpp"), source(version))
  library = File.join(dir, "libbench.so")
  run!("g++", "-g", "-O2", "-shared", "-fPIC", "-o", library, "lib.cpp", chdir: dir)
  id = run!("readelf", "-n", library)[/Build ID: (\h+)/, 1]
  debug = File.join(dir, "debug", ".build-id", id[0, 2], "#{id[2..]}.debug")
  FileUtils.mkdir_p(File.dirname(debug))
  run!("objcopy", "--only-keep-debug", library, debug)
  run!("strip", "--strip-debug", "--remove-section=.comment", library)
  run!("objcopy", "--add-gnu-debuglink=#{debug}", library)
  [library, File.join(dir, "debug")]
end

Dir.mktmpdir("relspec-bench-abi") do |dir|
  compiled = Timing.seconds { @old, @new = [1, 2].map { |version| build(File.join(dir, "v#{version}"), version) } }
  dumps = [@old, @new].each_with_index.map do |(library, debug), index|
    xml = File.join(dir, "#{index}.xml")
    [xml, debug, library]
  end
  dump_time = Timing.seconds do
    dumps.each do |xml, debug, library|
      run!(*Relspec::Builder::AbiDumper::ABIDW, "--debug-info-dir", debug, "--out-file", xml, library)
      Relspec::Builder::AbiDumper.compress(xml, "#{xml}.gz")
    end
  end
  verdict = nil
  stored = Timing.seconds { verdict = Relspec::Abi::Comparison.compare("#{dumps[0][0]}.gz", "#{dumps[1][0]}.gz") }
  peer_status = nil
  peer = Timing.seconds do
    _out, status = Open3.capture2e("abidiff", "--no-show-locs", "--d1", @old[1], "--d2", @new[1], @old[0], @new[0])
    peer_status = status.exitstatus
  end
  symbols = run!("nm", "-D", "--defined-only", @old[0]).lines.size
  printf("library: %d classes, %d exported symbols, %.1f MB stripped, %.1f MB debug; g++ took %.1f s for both\n",
         CLASSES, symbols, File.size(@old[0]) / 1e6,
         Dir.glob(File.join(@old[1], "**", "*.debug"), File::FNM_DOTMATCH).sum { |file| File.size(file) } / 1e6, compiled)
  printf("dumps (abidw + gzip, once per build): %.2f s for both; stored XML %.1f MB, gzip %.2f MB each\n",
         dump_time, File.size(dumps[0][0]) / 1e6, File.size("#{dumps[0][0]}.gz") / 1e6)
  printf("relspec abi, stored dumps:  %.2f s per library (verdict %s)\n", stored, verdict.verdict)
  printf("peer abidiff of the .so:    %.2f s per library (exit %d)\n", peer, peer_status)
  printf("ratio peer / relspec: %.1fx\n", peer / stored)
end
