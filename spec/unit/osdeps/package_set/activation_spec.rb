# frozen_string_literal: true

require_relative "../../unit_helper"
require "autoproj"
require "relspec/osdeps/package_set/activation"

# What init.rb reads before apt, /etc/apt or the environment see anything:
# the chosen release, its lineage and its packages for this system (through
# Osdeps::Reader), each refusal naming the file. A real Autoproj::Workspace
# on a temporary folder; the system is given (this_system asks dpkg, a child
# process). The whole run, apt included, is package_set_init_spec.rb's.
RSpec.describe RelspecPackageSet::Activation, :tmpdir do
  before do
    @data = File.join(@dir, "set", "data")
    FileUtils.mkdir_p([@data, File.join(@dir, "ws", "autoproj"), File.join(@dir, "ws", ".autoproj")])
    File.write(File.join(@data, "releases.yml"), "default: { repo_url: http://h }\nbase: ~\nr: { depends_on: base }\n")
    osdeps("base", "base/cmake" => "rock-base-cmake", "base/old" => "rock-base-old")
    osdeps("r", "base/cmake" => "rock-r-cmake")
    File.write(File.join(@dir, "ws", "autoproj", "relspec.yml"), "release: r\n")
  end

  def osdeps(release, packages)
    File.write(File.join(@data, "#{release}-amd64.yml"),
               YAML.dump(packages.transform_values { |deb| { "debian" => { "12,bookworm" => deb } } }))
  end

  let(:activation) { described_class.new(Autoproj::Workspace.new(File.join(@dir, "ws")), File.join(@dir, "set")) }
  let(:system) do
    RelspecPackageSet::System.new(Relspec::Osdeps::OperatingSystem.new(%w[debian], %w[12 bookworm default]), "amd64", "bookworm")
  end

  it "reads the chosen release, ancestors first, the release overriding them" do
    release = activation.send(:chosen_release)
    lineage = activation.send(:lineage, release)
    expect([release, lineage]).to eq(["r", %w[base r]])
    expect(activation.send(:mapping, lineage, system)).to eq("base/cmake" => "rock-r-cmake", "base/old" => "rock-base-old")
  end

  it "refuses a name that is not a Debian one, a cycle and a release not built for the system, naming the file" do
    osdeps("r", "base/cmake" => "-oX=y")
    expect { activation.send(:mapping, %w[base r], system) }
      .to raise_error(Autoproj::ConfigError, %r{r-amd64\.yml: base/cmake: "-oX=y" is not a Debian package name})
    File.write(File.join(@data, "releases.yml"), "base: { depends_on: r }\nr: { depends_on: base }\n")
    expect { activation.send(:lineage, "r") }.to raise_error(Autoproj::ConfigError, /releases\.yml: depends_on cycle through r\z/)
    osdeps("base", "base/cmake" => "rock-base-cmake")
    other = RelspecPackageSet::System.new(Relspec::Osdeps::OperatingSystem.new(%w[ubuntu], %w[focal]), "amd64", "focal")
    expect { activation.send(:mapping, %w[base], other) }
      .to raise_error(Autoproj::ConfigError, /the release base does not exist for ubuntu focal \(amd64\) \(it is built for debian 12,bookworm\)/)
  end

  # Issue 46, case 16: the user chose a child whose ancestor lacks the
  # system or the architecture; base-child-amd64.yml is not base's "child-amd64".
  it "names the release the user chose and the ancestor that lacks this system or architecture" do
    File.write(File.join(@data, "releases.yml"), "base: ~\nbase-child: { depends_on: base }\n")
    osdeps("base-child", "base/cmake" => "rock-child-cmake")
    other = RelspecPackageSet::System.new(Relspec::Osdeps::OperatingSystem.new(%w[ubuntu], %w[focal]), "amd64", "focal")
    expect { activation.send(:mapping, %w[base base-child], other) }
      .to raise_error(Autoproj::ConfigError, "relspec package set: the release base-child does not exist for ubuntu focal (amd64): " \
                                             "its ancestor base is not built for it (base is built for debian 12,bookworm)")
    File.rename(File.join(@data, "base-amd64.yml"), File.join(@data, "base-arm64.yml"))
    expect { activation.send(:mapping, %w[base base-child], system) }
      .to raise_error(Autoproj::ConfigError, "relspec package set: the release base-child does not exist for amd64: " \
                                             "its ancestor base is not built for it (base is built for arm64)")
  end
end
