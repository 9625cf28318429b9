# frozen_string_literal: true

require "spec_helper"
require_relative "../../support/apt_repository_builder"
require_relative "../../support/private_apt"

# The tests' private apt must not see what another test process installs into
# this machine meanwhile (package_set_workspace_spec installs rock-demo-*
# for real while example_release_spec asks apt to install the same names):
# a machine status holding a half-configured release package, as this
# machine's does during that test, still lets apt plan the install.
RSpec.describe PrivateApt do
  it "asks apt as a machine without the release's packages, whatever this machine has installed meanwhile" do
    Dir.mktmpdir("relspec-private-apt") do |dir|
      repository = File.join(dir, "repository")
      AptRepositoryBuilder.new(repository, codenames: ["bookworm"], architectures: ["amd64"])
                          .add("rock-demo-base-data-models", "3.1-1~bookworm", codename: "bookworm", arch: "all")
      status = File.join(dir, "machine-status")
      File.write(status, File.read(PrivateApt::MACHINE_STATUS).chomp + <<~STANZA)

        Package: rock-demo-base-data-models
        Status: install ok half-configured
        Priority: optional
        Section: misc
        Maintainer: relspec tests <tests@relspec.invalid>
        Architecture: all
        Version: 3.1-1~bookworm
        Description: installed by another test meanwhile
      STANZA
      apt = PrivateApt.new(File.join(dir, "apt"), [PrivateApt.source(repository, "bookworm")], machine_status: status)
      output, update = apt.update
      expect(update).to be_success, output

      output, = apt.simulate("rock-demo-base-data-models")
      expect(output).to match(/^Inst rock-demo-base-data-models /)
    end
  end
end
