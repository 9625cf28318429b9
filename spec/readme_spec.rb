# frozen_string_literal: true

require "spec_helper"

# The README's first two commands are the newcomer's contract; CI runs the
# second one, so the two must not drift apart.
RSpec.describe "README" do
  readme = File.read(File.join(CliRunner::ROOT, "README.md"))
  commands = readme[/```sh\n(.*?)```/m, 1].lines.map(&:strip)

  it "opens with the example command and the test command" do
    expect(readme.index("```sh")).to be < readme.index("## ")
    expect(commands.size).to eq(2)
    expect(commands[1]).to eq("bin/setup && bundle exec rubocop && bin/test")
  end

  it "has CI run exactly the test command" do
    ci = File.read(File.join(CliRunner::ROOT, ".ci", "run"))
    expect(ci.lines.map(&:strip)).to include(commands[1])
  end

  it "names only relspec commands that exist, in the example command and bin/demo" do
    demo = File.readlines(File.join(CliRunner::ROOT, "bin", "demo")).reject { |line| line.start_with?("#") }.join
    used = "#{commands[0]}\n#{demo}".scan(/relspec (\w+)/).flatten.uniq
    expect(used).to include("plan")
    help = relspec("help").stdout
    used.each { |command| expect(help).to include("relspec #{command}") }
  end
end

RSpec.describe "the README's example command" do
  # One run from scratch (host backend: the sbuild backend has its own test,
  # spec/relspec/build/sbuild_spec.rb): demo-base is compiled, built and
  # published, demo-child inherits from it and builds only what it must.
  # releases/ is committed (DESIGN §2): the run must give exactly what is
  # committed — the lock identifies the ancestor by what it provides, not by
  # its freshly dated Release file. When the example changes, `bin/demo`
  # regenerates releases/ (commit it).
  it "builds and publishes both releases for real and regenerates releases/ exactly as committed" do
    %w[examples/workspace build/repositories build/demo-base build/demo-child].each do |dir|
      FileUtils.rm_rf(File.join(CliRunner::ROOT, dir))
    end
    output, status = Open3.capture2e({ "RELSPEC_DEMO_BACKEND" => "host" }, File.join(CliRunner::ROOT, "bin", "demo"))
    expect(status).to be_success, output
    expect(output).to include("2 specs valid: specs/demo-base.yml specs/demo-child.yml")
    expect(output).to include('blacklisted by "base/types" (the project needs the 2020 types API)')
    expect(output).to include("depends on base/types, which is rebuilt because blacklisted by")
    pool = Dir.glob(File.join(CliRunner::ROOT, "build", "repositories", "*", "pool", "**", "*.deb"))
    child = pool.grep(%r{/demo-child/}).map { |deb| File.basename(deb).split("_").first }
    expect(child).to include("rock-demo-child-base-types")
    expect(child).not_to include("rock-demo-child-base-cmake") # inherited from demo-base
    expect(pool.grep(%r{/demo-base/}).map { |deb| File.basename(deb).split("_").first }).to include("rock-demo-base-base-cmake")

    diff, diff_status = Open3.capture2e("git", "-C", CliRunner::ROOT, "diff", "--exit-code", "--", "releases/")
    expect(diff_status).to be_success, "releases/ differs from what is committed (run bin/demo and commit):\n#{diff}"
    untracked, = Open3.capture2e("git", "-C", CliRunner::ROOT, "status", "--porcelain", "--", "releases/")
    expect(untracked).to eq("")
    check = relspec("plan", "--check")
    expect([check.stdout, check.exit_code]).to eq(["", 0])
  end
end
