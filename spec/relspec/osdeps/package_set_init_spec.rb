# frozen_string_literal: true

require "spec_helper"
require "json"
require "relspec/osdeps/package_set"
require_relative "../../support/machine_apt"

# The package set's init.rb on hostile data (issue 33), the second line of
# defence after relspec's writer (spec/hostile/package_set_spec.rb): a
# package set is a git checkout anybody with push access changes, and
# init.rb runs in every autoproj command, with sudo for apt. Each case is a
# package set that differs from a well-formed one in one entry; real
# autoproj loads its init.rb into a real Autoproj::Workspace
# (spec/support/package_set_init_driver.rb: one process, a fork per case)
# and each must stop naming the file and the entry before anything reaches
# autoproj's osdeps (its `apt-get install`), /etc/apt, apt's lists or the
# workspace's environment. The well-formed set is the control: it goes on
# to write its apt source and run apt-get update (which fails: nothing
# serves 127.0.0.1:1). Root, as CI: the installed env.yml files the
# environment cases need live below /opt/rock; MachineApt puts /etc/apt back
# as it found it.
RSpec.describe "the package set's init.rb on hostile data" do
  RELEASE = "zz-relspec-init-test"
  PREFIX = File.join("/opt/rock", RELEASE)
  GOOD_OSDEPS = "base/cmake:\n  debian:\n    12,bookworm: rock-zz-base-cmake\n"
  GOOD_APT = { RELEASE => { "url" => "http://127.0.0.1:1/#{RELEASE}", "trusted" => false,
                            "key" => "keys/#{RELEASE}.gpg" } }.freeze

  def self.cases
    @cases ||= {}
  end

  # A case: +change+ edits the well-formed package set (folder) and
  # workspace (autoproj/ folder).
  def self.hostile(name, &change)
    cases[name] = change
  end

  def self.osdeps(deb)
    ->(set, _) { File.write(File.join(set, "data", "#{RELEASE}-amd64.yml"), GOOD_OSDEPS.sub("rock-zz-base-cmake", deb)) }
  end

  def self.apt(entry)
    ->(set, _) { File.write(File.join(set, "data", "apt.yml"), YAML.dump(RELEASE => entry)) }
  end

  # An installed package's env.yml (below /opt/rock, as dpkg leaves it) of
  # the Debian package +deb+, which the case's osdeps file names.
  def self.environment(deb, text)
    lambda do |set, _|
      osdeps(deb).call(set, nil)
      FileUtils.mkdir_p(File.join(PREFIX, deb))
      File.write(File.join(PREFIX, deb, "env.yml"), text)
    end
  end

  def self.relspec_yml(text)
    ->(_, config) { File.write(File.join(config, "relspec.yml"), text) }
  end

  hostile(:control) { |_, _| nil }
  hostile(:option_name, &osdeps("-oDPkg::Pre-Invoke::=touch /tmp/pwned"))
  hostile(:spaced_name, &osdeps("rock-a rock-b"))
  hostile(:shell_name, &osdeps("rock-a;reboot"))
  hostile(:traversing_name, &osdeps("../../../tmp/x"))
  hostile(:untrusted_without_key, &apt("url" => "http://127.0.0.1:1/#{RELEASE}", "trusted" => false))
  hostile(:url_with_newline, &apt("url" => "http://127.0.0.1:1/a\ndeb [trusted=yes] http://evil.example/b", "trusted" => true))
  hostile(:url_not_http, &apt("url" => "file:///srv/#{RELEASE}", "trusted" => true))
  hostile(:key_outside, &apt(GOOD_APT[RELEASE].merge("key" => "../../../../../../etc/hostname")))
  hostile(:key_symlink_outside) do |set, _|
    File.delete(File.join(set, "data", "keys", "#{RELEASE}.gpg"))
    File.symlink("/etc/hostname", File.join(set, "data", "keys", "#{RELEASE}.gpg"))
  end
  hostile(:release_name_traversing) do |set, _|
    File.write(File.join(set, "data", "releases.yml"), "#{RELEASE}:\n  depends_on: ../../etc\n")
  end
  hostile(:ld_preload, &environment("rock-zz-preload", "LD_PRELOAD:\n  :type: :set\n  :values: [\"#{PREFIX}/x.so\"]\n"))
  hostile(:library_path_outside, &environment("rock-zz-libpath", "LD_LIBRARY_PATH:\n  :type: :add_path\n  :values: [\"/tmp/lib\"]\n"))
  hostile(:library_path_dots,
          &environment("rock-zz-dots", "LD_LIBRARY_PATH:\n  :type: :add_path\n  :values: [\"#{PREFIX}/../../../tmp\"]\n"))
  hostile(:env_file_symlink_outside) do |set, _|
    osdeps("rock-zz-symlink").call(set, nil)
    FileUtils.mkdir_p(File.join(PREFIX, "rock-zz-symlink"))
    File.write(File.join(set, "evil-env.yml"), "LD_PRELOAD:\n  :type: :set\n  :values: [/tmp/x.so]\n")
    File.symlink(File.join(set, "evil-env.yml"), File.join(PREFIX, "rock-zz-symlink", "env.yml"))
  end
  hostile(:relspec_yml_bare_name, &relspec_yml("#{RELEASE}\n"))
  hostile(:relspec_yml_list, &relspec_yml("- release: #{RELEASE}\n"))
  hostile(:relspec_yml_misspelt, &relspec_yml("relase: #{RELEASE}\n"))
  hostile(:relspec_yml_release_list, &relspec_yml("release: [#{RELEASE}]\n"))
  hostile(:relspec_yml_not_yaml, &relspec_yml("release: [\n"))
  # Issue 46, case 16: the user chose a child release whose parent (this
  # package set's RELEASE) lacks the system or the architecture.
  def self.child_of(change)
    lambda do |set, config|
      File.write(File.join(set, "data", "releases.yml"),
                 "default:\n  repo_url: http://127.0.0.1:1\n#{RELEASE}:\n#{RELEASE}-child:\n  depends_on: #{RELEASE}\n")
      File.write(File.join(set, "data", "#{RELEASE}-child-amd64.yml"), GOOD_OSDEPS.sub("rock-zz-", "rock-zz-child-"))
      File.write(File.join(config, "relspec.yml"), "release: #{RELEASE}-child\n")
      change.call(File.join(set, "data"))
    end
  end
  hostile(:parent_without_system,
          &child_of(->(data) { File.write(File.join(data, "#{RELEASE}-amd64.yml"), GOOD_OSDEPS.sub("debian", "ubuntu")) }))
  hostile(:parent_without_arch,
          &child_of(->(data) { File.rename(File.join(data, "#{RELEASE}-amd64.yml"), File.join(data, "#{RELEASE}-arm64.yml")) }))
  hostile(:blacklist_broken_regex) { |_, config| File.write(File.join(config, "deb_blacklist.yml"), "- drivers/(\n") }

  before(:all) do
    raise "init.rb's environment cases install env.yml below /opt/rock: run as root (CI does)" unless Process.uid.zero?

    @machine = MachineApt.new("rock-zz-*")
    @dir = Dir.mktmpdir("relspec-init")
    folders = self.class.cases.map do |name, change|
      set = File.join(@dir, name.to_s, "package-set")
      root = File.join(@dir, name.to_s, "ws")
      write_package_set(set)
      FileUtils.mkdir_p([File.join(root, "autoproj"), File.join(root, ".autoproj")])
      File.write(File.join(root, "autoproj", "relspec.yml"), "release: #{RELEASE}\n")
      change.call(set, File.join(root, "autoproj"))
      [root, set]
    end
    output = File.join(@dir, "results.json")
    driver = File.expand_path("../../support/package_set_init_driver.rb", __dir__)
    log, status = Bundler.with_unbundled_env { Open3.capture2e(RbConfig.ruby, driver, output, *folders.flatten) }
    raise "the init.rb driver failed:\n#{log}" unless status.success?

    @results = self.class.cases.keys.zip(JSON.parse(File.read(output))).to_h
  end

  after(:all) do
    @machine&.restore
    FileUtils.rm_rf(PREFIX)
    FileUtils.rm_rf(@dir) if @dir
  end

  # The well-formed package set: what `relspec osdeps package-set` writes
  # for one signed release (lib/ and init.rb as shipped).
  def write_package_set(set)
    package_set = Relspec::Osdeps::PackageSet
    files = { "source.yml" => "name: #{package_set::NAME}\n", "init.rb" => File.read(package_set::INIT),
              "data/releases.yml" => "default:\n  repo_url: http://127.0.0.1:1\n#{RELEASE}:\n",
              "data/#{RELEASE}-amd64.yml" => GOOD_OSDEPS, "data/apt.yml" => YAML.dump(GOOD_APT),
              "data/keys/#{RELEASE}.gpg" => "not a real key: apt never gets to read it\n",
              "data/packages/#{RELEASE}/bookworm/amd64.yml" => "rock-zz-base-cmake: {}\n" }
    package_set.shipped.each { |path| files["lib/#{path}"] = File.read(File.join(package_set::LIB, path)) }
    files.each do |path, content|
      FileUtils.mkdir_p(File.dirname(File.join(set, path)))
      File.write(File.join(set, path), content)
    end
  end

  # What a refused case must show: its message, and that nothing reached
  # autoproj's osdeps, apt or the environment.
  def refused(name)
    result = @results.fetch(name)
    expect(result["apt_changed"]).to be(false)
    expect(result["osdeps"]).not_to include("base/cmake")
    expect(result["env"]).to eq({})
    result["message"]
  end

  def data(name, file)
    File.join(@dir, name.to_s, "package-set", "data", file)
  end

  it "lets a well-formed package set through to autoproj's osdeps and apt (the control)" do
    result = @results.fetch(:control)
    expect(result["osdeps"]).to include("base/cmake")
    expect(result["message"]).to include("relspec package set: timeout 300 apt-get update -o Dir::Etc::sourcelist=" \
                                         "/etc/apt/sources.list.d/relspec-#{RELEASE}.list")
    expect(result["apt_changed"]).to be(true)
  end

  it "refuses Debian names apt would read as an option, or that hold spaces, shell syntax or ../" do
    osdeps = data(:option_name, "#{RELEASE}-amd64.yml")
    expect(refused(:option_name)).to eq("relspec package set: #{osdeps}: base/cmake: \"-oDPkg::Pre-Invoke::=touch " \
                                        "/tmp/pwned\" is not a Debian package name (lowercase letters, digits, + - ., " \
                                        "not starting with - or .)")
    { spaced_name: "rock-a rock-b", shell_name: "rock-a;reboot", traversing_name: "../../../tmp/x" }.each do |name, deb|
      expect(refused(name)).to start_with("relspec package set: #{data(name, "#{RELEASE}-amd64.yml")}: base/cmake: " \
                                          "#{deb.inspect} is not a Debian package name")
    end
  end

  it "refuses an apt source without a key that its spec did not call trusted" do
    expect(refused(:untrusted_without_key)).to eq("relspec package set: #{data(:untrusted_without_key, 'apt.yml')}: " \
                                                  "#{RELEASE}: has no key and does not say trusted: true: apt would " \
                                                  "read it unverified")
  end

  it "refuses URLs that are not plain http(s) URLs (a newline would add an apt line)" do
    expect(refused(:url_with_newline)).to eq("relspec package set: #{data(:url_with_newline, 'apt.yml')}: #{RELEASE}: " \
                                             "the URL \"http://127.0.0.1:1/a\\ndeb [trusted=yes] http://evil.example/b\" " \
                                             "is not a plain http(s) URL")
    expect(refused(:url_not_http)).to include("the URL \"file:///srv/#{RELEASE}\" is not a plain http(s) URL")
  end

  it "refuses key paths outside the package set, written so or through a symbolic link" do
    expect(refused(:key_outside)).to eq("relspec package set: #{data(:key_outside, 'apt.yml')}: #{RELEASE}: the key " \
                                        "\"../../../../../../etc/hostname\" is not a keys/<release>.gpg of the package set")
    expect(refused(:key_symlink_outside)).to eq("relspec package set: #{data(:key_symlink_outside, 'apt.yml')}: " \
                                                "#{RELEASE}: the key keys/#{RELEASE}.gpg is not a file of the package set")
  end

  it "refuses release names that would become paths outside the package set" do
    expect(refused(:release_name_traversing)).to eq("relspec package set: #{data(:release_name_traversing, 'releases.yml')}: " \
                                                    "\"#{RELEASE}\": \"../../etc\" is not a release name")
  end

  it "refuses env.yml variables outside the allow-list, paths outside the prefix and env files outside it" do
    env = ->(deb) { File.join(PREFIX, deb, "env.yml") }
    expect(refused(:ld_preload)).to eq("relspec package set: #{env['rock-zz-preload']}: \"LD_PRELOAD\" is not a " \
                                       "variable the package set lets a package change")
    expect(refused(:library_path_outside)).to eq("relspec package set: #{env['rock-zz-libpath']}: LD_LIBRARY_PATH: " \
                                                 "\"/tmp/lib\" is not a path below /opt/rock")
    expect(refused(:library_path_dots)).to include("LD_LIBRARY_PATH: \"#{PREFIX}/../../../tmp\" is not a path below /opt/rock")
    expect(refused(:env_file_symlink_outside)).to eq(
      "relspec package set: #{env['rock-zz-symlink']}: is #{File.join(@dir, 'env_file_symlink_outside', 'package-set', 'evil-env.yml')}, " \
      "outside /opt/rock"
    )
  end

  it "names the file, the key and what is expected for every shape of autoproj/relspec.yml" do
    config = ->(name) { File.join(@dir, name.to_s, "ws", "autoproj", "relspec.yml") }
    expected = "expected `release: <name>` (one of #{RELEASE})"
    expect(refused(:relspec_yml_bare_name)).to eq("relspec package set: #{config[:relspec_yml_bare_name]}: is " \
                                                  "\"#{RELEASE}\" (a string), #{expected}")
    expect(refused(:relspec_yml_list)).to eq("relspec package set: #{config[:relspec_yml_list]}: is a list, #{expected}")
    expect(refused(:relspec_yml_misspelt)).to eq("relspec package set: #{config[:relspec_yml_misspelt]}: unknown key " \
                                                 "\"relase\", #{expected}")
    expect(refused(:relspec_yml_release_list)).to eq("relspec package set: #{config[:relspec_yml_release_list]}: " \
                                                     "release: is a list, #{expected}")
    expect(refused(:relspec_yml_not_yaml)).to start_with("relspec package set: #{config[:relspec_yml_not_yaml]}: is not plain YAML (")
  end

  it "names the release the user chose and the ancestor that lacks this system or architecture" do
    expect(refused(:parent_without_system)).to match(
      /\Arelspec package set: the release #{RELEASE}-child does not exist for debian \S+ \(amd64\): its ancestor #{RELEASE} is not built for it \(#{RELEASE} is built for ubuntu 12,bookworm\)\z/
    )
    expect(refused(:parent_without_arch)).to eq("relspec package set: the release #{RELEASE}-child does not exist for amd64: " \
                                                "its ancestor #{RELEASE} is not built for it (#{RELEASE} is built for arm64)")
  end

  it "names the entry of a blacklist pattern that cannot match, once" do
    path = File.join(@dir, "blacklist_broken_regex", "ws", "autoproj", "deb_blacklist.yml")
    expect(refused(:blacklist_broken_regex)).to start_with("relspec package set: #{path} entry 1: \"drivers/(\" is not")
    expect(refused(:blacklist_broken_regex).scan("drivers/(").size).to eq(1)
  end
end
