# frozen_string_literal: true

require "spec_helper"
require "json"
require "yaml"

# The shipped example for real on this machine's distribution (bookworm/amd64):
# demo-base compiled, built (`relspec build --backend host`) and published; demo-child planned against
# that repository, so it builds only base/types and its reverse dependencies,
# built against demo-base's packages and published next to them. Then apt
# installs every package of demo-child (simulated, through a private apt
# configuration with both repositories and this machine's archive), and an
# installed demo-child package finds its inherited demo-base dependency
# through env.sh. The specs are the project's own, in a copy of the project.
RSpec.describe "the example releases, built and published on bookworm" do
  def target_name
    "bookworm/amd64"
  end

  before(:all) do
    @dir = Dir.mktmpdir("relspec-example")
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    %w[demo-base demo-child].each { |name| FileUtils.cp(File.join(CliRunner::ROOT, "specs", "#{name}.yml"), File.join(@dir, "specs")) }
    DemoWorkspace.build(File.join(@dir, "examples"))
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def run!(*args)
    run = relspec(*args, chdir: @dir)
    raise "relspec #{args.join(' ')} failed: #{run.stderr}" unless run.status.success?

    run
  end

  def repository(release)
    File.join(@dir, "build", "repositories", release)
  end

  def osdeps(release)
    YAML.safe_load_file(File.join(repository(release), "osdeps", "#{release}-amd64.yml"))
  end

  def deb_names(release)
    osdeps(release).values.map { |entry| entry.fetch("debian").fetch("12,bookworm") }
  end

  # apt reads the repositories (updated into a private lists folder) and
  # this machine's archive (its lists copied in: no network).
  def private_apt(dir)
    apt = PrivateApt.new(dir, %w[demo-base demo-child].map { |release| PrivateApt.source(repository(release), "bookworm") })
    output, status = apt.update
    raise output unless status.success?

    Dir.glob("/var/lib/apt/lists/*_{Packages,InRelease,Release}*").each { |file| FileUtils.cp(file, File.join(dir, "lists")) }
    apt
  end

  it "builds only what demo-child changes, and apt installs all of demo-child" do
    run!("compile", "specs/demo-base.yml", "--out", "out")
    run!("build", "specs/demo-base.yml", "--out", "out", "--backend", "host", "--target", target_name)
    run!("publish", "specs/demo-base.yml", "--out", "out", "--target", target_name)
    expect(deb_names("demo-base").size).to eq(7)

    plan = JSON.parse(run!("plan", "specs/demo-child.yml", "--format", "json", "--target", target_name).stdout)
    decisions = plan.fetch("targets").fetch(target_name).transform_values { |entry| entry["decision"] }
    expect(decisions.select { |_, decision| decision == "build" }.keys)
      .to contain_exactly("base/types", "drivers/iodrivers_base", "tools/orocos.rb")
    expect(decisions.values.tally).to eq("build" => 3, "inherit" => 4)

    run!("compile", "specs/demo-child.yml", "--out", "out")
    run!("build", "specs/demo-child.yml", "--out", "out", "--backend", "host", "--target", target_name)
    run!("publish", "specs/demo-child.yml", "--out", "out", "--target", target_name)
    names = deb_names("demo-child")
    expect(names.grep(/\Arock-demo-child-/).size).to eq(3)
    expect(names.grep(/\Arock-demo-base-/).size).to eq(4)

    Dir.mktmpdir("relspec-apt") do |apt_dir|
      apt = private_apt(apt_dir)
      names.each do |name|
        output, status = Open3.capture2e("apt-get", *apt.options, "-o", "Dir::Etc::sourceparts=/etc/apt/sources.list.d",
                                         "install", "--simulate", "--no-install-recommends", name)
        expect(status).to be_success, "#{name}: #{output}"
        expect(output).to match(/^Inst #{Regexp.escape(name)} /)
      end
    end

    # demo-child's driver, really installed (unpacked at /opt in a private
    # mount namespace), finds demo-base's logging through env.sh
    host = UnpackedRoot.new(File.join(@dir, "installed"))
    Dir.glob(File.join(@dir, "out", "demo-{base,child}", "*", "results", "*", "*.deb")).each { |deb| host.install(deb) }
    driver = "/opt/rock/demo-child/rock-demo-child-drivers-iodrivers-base"
    output, status = host.shell(". #{driver}/env.sh && echo \"$CMAKE_PREFIX_PATH\"")
    expect(status).to be_success, output
    expect(output.strip.split(":")).to include(driver, "/opt/rock/demo-base/rock-demo-base-base-logging",
                                               "/opt/rock/demo-child/rock-demo-child-base-types")
  end
end
