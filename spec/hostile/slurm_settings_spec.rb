# frozen_string_literal: true

require "spec_helper"

# Bad cluster settings for `relspec build --engine slurm` (.relspec/slurm.yml
# and --slurm KEY=VALUE), through the real CLI: each is refused with one
# message naming the file and line (or the option), exit 1, before relspec
# reads the spec or talks to Slurm (no cluster is needed to see it).
RSpec.describe "relspec build --engine slurm with hostile cluster settings", :tmpdir do
  def build(*args)
    # the spec does not exist: the settings are refused before it is read
    run = relspec("build", "specs/none.yml", "--engine", "slurm", *args, chdir: @dir,
                                                                         env: { "XDG_CONFIG_HOME" => @dir })
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to eq("")
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
    expect(run.stderr.lines.size).to eq(1)
    run.stderr
  end

  def settings(text, path: File.join(@dir, ".relspec", "slurm.yml"))
    FileUtils.mkdir_p(File.dirname(path))
    File.write(path, text)
    path
  end

  it "names the line of a setting it does not know" do
    path = settings("partition: build\npartiton: typo\n")
    expect(build).to eq("relspec: error: #{path}:2: error[slurm-settings]: unknown setting \"partiton\" (known: " \
                        "partition, account, time_limit, memory, cpus_per_build, shared_folder, poll_interval, " \
                        "features)\n")
  end

  it "names the line of a value of the wrong kind, in the user's file too" do
    path = settings("memory: 4G\ncpus_per_build: -2\n", path: File.join(@dir, "relspec", "slurm.yml"))
    expect(build).to eq("relspec: error: #{path}:2: error[slurm-settings]: cpus_per_build must be a positive whole number\n")
  end

  it "refuses a file that is not YAML, and one that is not a mapping" do
    path = settings("partition: [build\n")
    expect(build).to start_with("relspec: error: #{path}:1: error[slurm-settings]: cannot be read (did not find expected")
    settings("- partition\n")
    expect(build).to eq("relspec: error: #{path}:1: error[slurm-settings]: not a mapping of settings\n")
  end

  it "refuses --slurm values it cannot use" do
    expect(build("--slurm", "partition")).to eq("relspec: error: --slurm partition: error[slurm-settings]: not KEY=VALUE\n")
    expect(build("--slurm", "poll_interval=soon"))
      .to eq("relspec: error: --slurm poll_interval=soon: error[slurm-settings]: poll_interval must be a number\n")
  end
end
