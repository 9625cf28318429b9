# frozen_string_literal: true

require "spec_helper"

# Unknown subcommands and options of every command group (issue 24, item
# 3): one "relspec: error:" line with a hint, exit 1, and never taken as an
# argument of another command (`relspec osdeps package-set`, before that
# command existed, ran `osdeps render package-set`).
RSpec.describe "relspec on a command line it does not know", :tmpdir do
  {
    %w[osdeps frobnicate x] => 'relspec osdeps has no command "frobnicate" (commands: help, index, package-set, render, select, tree)',
    %w[osdeps slect] => 'relspec osdeps has no command "slect" (commands: help, index, package-set, render, select, tree); ' \
                        'did you mean "select"?',
    %w[osdeps package-sett x] => 'relspec osdeps has no command "package-sett" (commands: help, index, package-set, render, ' \
                                 'select, tree); did you mean "package-set"?',
    %w[catalog shwo x] => 'relspec catalog has no command "shwo" (commands: export, help, show, tree); did you mean "show"?',
    %w[publsh x] => 'relspec has no command "publsh" (commands: abi, build, catalog, check, compile, diff, help, mirror, ' \
                    'osdeps, plan, publish, report, show, tree, validate, version, why); did you mean "publish"?',
    %w[build x.yml --jbos 2] => 'unknown option --jbos; did you mean "--jobs"?',
    %w[diff --bsae main] => 'unknown option --bsae; did you mean "--base"?',
    %w[osdeps render x.yml --from-repo] => 'unknown option --from-repo; did you mean "--from-repository"?',
    %w[catalog show x.yml --tagret bionic] => 'unknown option --tagret; did you mean "--target"?',
    %w[osdeps index --frob] => "unknown option --frob",
    %w[osdeps render] => "usage: relspec osdeps render SPEC; got no arguments",
    %w[check a.yml b.yml] => "usage: relspec check SPEC; got the arguments a.yml b.yml"
  }.each do |args, message|
    it "refuses `relspec #{args.join(' ')}` before reading anything" do
      run = relspec(*args, chdir: @dir)
      expect([run.exit_code, run.stderr, run.stdout]).to eq([1, "relspec: error: #{message}\n", ""])
    end
  end

  it "still takes `relspec osdeps SPEC` as `osdeps render SPEC`" do
    run = relspec("osdeps", "specs/none.yml", chdir: @dir)
    expect([run.exit_code, run.stderr]).to eq([1, "specs/none.yml: error[unreadable-file]: cannot read the file: " \
                                                  "No such file or directory\n1 error in 1 file\n"])
  end
end
