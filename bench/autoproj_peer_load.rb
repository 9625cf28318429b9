# frozen_string_literal: true

# The peer of bench/catalog: autoproj's own load of a workspace, the steps
# `autoproj show` goes through before printing (set up the workspace, load
# package sets, set up package directories, run the package setup blocks,
# read every manifest.xml), with nothing of relspec in the process.
#
#   ruby bench/autoproj_peer_load.rb WORKSPACE
require "autoproj"

root = ARGV.fetch(0)
$stdout.reopen($stderr)
resolver = Autoproj::OSPackageResolver.new(operating_system: [%w[ubuntu debian], %w[18.04 bionic beaver default]])
# Like relspec, no package manager may set up environments or prompt.
inert = Class.new(Autoproj::PackageManagers::Manager) do
  def initialize_environment; end

  def configure_manager; end
end
managers = Autoproj::OSPackageInstaller::PACKAGE_MANAGERS.keys.to_h { |name| [name, inert] }
ws = Autoproj::Workspace.from_dir(root, os_package_resolver: resolver, package_managers: managers)
ws.config.interactive = false
ws.setup(read_only: true, load_global_configuration: false)
resolver.add_entries({ ws.ruby_version_keyword => "ignore" }) unless resolver.include?(ws.ruby_version_keyword)
ws.load_package_sets(only_local: true, checkout_only: true)
ws.setup_all_package_directories
ws.finalize_package_setup
ws.manifest.each_package_definition do |definition|
  ws.manifest.load_package_manifest(definition.name) if definition.checked_out?
end
ws.finalize_setup(read_only: true)
