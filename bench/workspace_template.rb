# frozen_string_literal: true

# bench/workspace_template: what a test fixture pays for the demo workspace
# (spec/support/demo_workspace.rb), median of RUNS.
#
#   bundle exec ruby bench/workspace_template.rb [RUNS]
#
# relspec's tests: a copy of the workspace this process already made
# (WorkspaceBuilder::Templates: cp -a, clone URLs rewritten). Peer: making
# it with git as every fixture did before (repositories, commits, tags,
# clones: ~60 git commands).
require "tmpdir"
require_relative "timing"
require_relative "../spec/support/demo_workspace"

RUNS = Integer(ARGV.fetch(0, "3"))

Dir.mktmpdir("bench-workspace") do |dir|
  demo = DemoWorkspace.build(File.join(dir, "first")) # makes the template
  made = 0
  fresh = Timing.median(RUNS) { WorkspaceBuilder.new(File.join(dir, "fresh#{made += 1}")).build_like(demo) }
  copied = Timing.median(RUNS) { DemoWorkspace.build(File.join(dir, "copy#{made += 1}")) }
  puts format("demo workspace made with git (peer): %.2f s", fresh)
  puts format("copy of this process's template:    %.2f s (%.2f× the peer)", copied, copied / fresh)
end
