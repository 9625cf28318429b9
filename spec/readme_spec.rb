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
    expect(commands[1]).to eq("bin/setup && bundle exec rspec")
  end

  it "has CI run exactly the test command" do
    ci = File.read(File.join(CliRunner::ROOT, ".ci", "run"))
    expect(ci.lines.map(&:strip)).to include(commands[1])
  end

  it "names only relspec commands that exist" do
    used = commands[0].scan(/relspec (\w+)/).flatten.uniq
    help = relspec("help").stdout
    used.each { |command| expect(help).to include("relspec #{command}") }
  end
end

RSpec.describe "the README's example command" do
  it "creates the example workspace and lists the child release's packages" do
    create = Open3.capture2e(RbConfig.ruby, File.join(CliRunner::ROOT, "examples", "create-workspace"))
    expect(create[1]).to be_success, create[0]
    expect(relspec("validate").exit_code).to eq(0)
    run = relspec("catalog", "show", "specs/demo-child.yml")
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout.lines.first).to eq("bionic: 7 packages from examples/workspace\n")
    # base/types at the commit its pin (tag v2.0.0) names
    expect(run.stdout).to match(%r{^  base/types\s+cmake\s+\h{10} 2020-03-02T14:00:00Z$})
  end
end
