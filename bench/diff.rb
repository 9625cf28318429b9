# frozen_string_literal: true

# bench/diff: `relspec diff OLD NEW` of two generated 400-package locks (50
# packages rebuilt per target; spec/support/large_locks.rb), against
# `diff -u` of the same two files — the floor any comparison of the files
# pays. Printed: the CLI run (markdown and text), the in-process diff, the
# peer, and the ratio. Target: < 0.5 s for the CLI run.
#
#   bundle exec ruby bench/diff.rb [RUNS]
require "open3"
require "rbconfig"
require "tmpdir"
require_relative "timing"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/diff"
require_relative "../spec/support/large_locks"

RUNS = Integer(ARGV.fetch(0, "9"))
EXE = File.expand_path("../exe/relspec", __dir__)

Dir.mktmpdir("relspec-bench-diff") do |dir|
  old, new = LargeLocks.write(dir)
  run = lambda do |*command|
    _out, status = Open3.capture2(*command)
    raise "#{command.join(' ')} failed" unless status.exitstatus <= 1
  end
  cli_markdown = Timing.median(RUNS) { run.call(RbConfig.ruby, EXE, "diff", old, new, "--format", "markdown") }
  cli_text = Timing.median(RUNS) { run.call(RbConfig.ruby, EXE, "diff", old, new) }
  planner = ->(_) { raise "no spec here" }
  in_process = Timing.median(RUNS) do
    pair = [old, new].map { |path| Relspec::Diff::Input.snapshot(path, planner: planner) }
    Relspec::Diff.render([Relspec::Diff::ReleaseDiff.compare(*pair)], "markdown")
  end
  peer = Timing.median(RUNS) { run.call("diff", "-u", old, new) }
  size = Relspec::Diff.render([Relspec::Diff::ReleaseDiff.compare(*[old, new].map { |p| Relspec::Diff::Input.snapshot(p, planner: planner) })],
                              "markdown").size
  puts format("400 packages, 2 targets, 50 rebuilt per target (median of %d)", RUNS)
  puts format("relspec diff --format markdown  %.3f s   (%d characters)", cli_markdown, size)
  puts format("relspec diff (text)             %.3f s", cli_text)
  puts format("in-process diff + markdown      %.3f s", in_process)
  puts format("peer: diff -u of the two locks  %.3f s", peer)
  puts format("ratio CLI / peer                %.0f×", cli_markdown / peer)
end
