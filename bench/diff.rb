# frozen_string_literal: true

# bench/diff: `relspec diff OLD NEW` of two generated 400-package locks (50
# packages rebuilt per target; spec/support/large_locks.rb), against
# `diff -u` of the same two files — the floor any comparison of the files
# pays. Printed: the CLI run three ways (as an installed gem, no Bundler;
# `ruby -rbundler/setup`; `bundle exec`), the text format, the in-process
# diff, the peer, and the ratios. Target: < 0.5 s for the CLI run.
#
#   bundle exec ruby bench/diff.rb [RUNS]
require "open3"
require "rbconfig"
require "tmpdir"
require_relative "timing"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/diff"
require_relative "../spec/support/large_locks"

RUNS = Integer(ARGV.fetch(0, "5"))
ROOT = File.expand_path("..", __dir__)
EXE = File.join(ROOT, "exe", "relspec")
# Children start clean: no RUBYOPT inherited from `bundle exec`, so each
# pays for Bundler only when the command line asks for it.
ENVIRONMENT = { "RUBYOPT" => nil, "BUNDLE_GEMFILE" => File.join(ROOT, "Gemfile") }.freeze

Dir.mktmpdir("relspec-bench-diff") do |dir|
  old, new = LargeLocks.write(dir)
  run = lambda do |*command|
    _out, status = Open3.capture2(ENVIRONMENT, *command)
    raise "#{command.join(' ')} failed" unless status.exitstatus <= 1
  end
  markdown = ["diff", old, new, "--format", "markdown"]
  gem_markdown = Timing.median(RUNS) { run.call(RbConfig.ruby, EXE, *markdown) }
  setup_markdown = Timing.median(RUNS) { run.call(RbConfig.ruby, "-rbundler/setup", EXE, *markdown) }
  bundle_markdown = Timing.median(RUNS) { run.call("bundle", "exec", EXE, *markdown) }
  gem_text = Timing.median(RUNS) { run.call(RbConfig.ruby, EXE, "diff", old, new) }
  planner = ->(_) { raise "no spec here" }
  diff = lambda do
    pair = [old, new].map { |path| Relspec::Diff::Input.snapshot(path, planner: planner) }
    Relspec::Diff.render([Relspec::Diff::ReleaseDiff.compare(*pair)], "markdown")
  end
  in_process = Timing.median(RUNS) { diff.call }
  ruby_start = Timing.median(RUNS) { run.call(RbConfig.ruby, "-e", "1") }
  peer = Timing.median(RUNS) { run.call("diff", "-u", old, new) }
  puts format("400 packages, 2 targets, 50 rebuilt per target (median of %d)", RUNS)
  puts format("relspec diff --format markdown, no Bundler   %.3f s   (%d characters)", gem_markdown, diff.call.size)
  puts format("  same, ruby -rbundler/setup                 %.3f s", setup_markdown)
  puts format("  same, bundle exec                          %.3f s", bundle_markdown)
  puts format("relspec diff (text), no Bundler              %.3f s", gem_text)
  puts format("in-process: read both locks, diff, markdown  %.3f s", in_process)
  puts format("ruby -e 1 (interpreter start)                %.3f s", ruby_start)
  puts format("peer: diff -u of the two locks               %.3f s", peer)
  puts format("ratio CLI (no Bundler) / peer                %.0f×", gem_markdown / peer)
  puts format("ratio CLI (bundle exec) / peer               %.0f×", bundle_markdown / peer)
end
