# frozen_string_literal: true

# The unit layer: one spec file per core file of lib/, fed in memory. It
# loads only the file under test (no spec_helper: no fixtures, servers or
# CLI runner) and refuses child processes, so that
# `bundle exec rspec spec/unit` stays well under a minute. A real HTTP
# server on 127.0.0.1 is a thread, not a child, and is allowed.

$LOAD_PATH.unshift(File.expand_path("../../lib", __dir__))
require "rspec"
require "tmpdir"

# What keeps the unit layer in memory.
module UnitLayer
  # Raised when code under a unit test starts a child process.
  class ChildProcess < StandardError; end

  # Guards the ways Ruby starts children (Open3 and IO.popen go through
  # Process.spawn) while a unit example runs; other examples of the same
  # rspec run are untouched.
  module NoChildren
    NAMES = %i[spawn system exec fork `].freeze

    NAMES.each do |name|
      define_method(name) do |*args, **options, &block|
        raise ChildProcess, "a unit test started a child process (#{name} #{args.first.inspect})" if Thread.current[:relspec_unit]

        super(*args, **options, &block)
      end
    end
  end

  # Kernel's methods are private in objects: so are the guards there.
  module PrivateNoChildren
    include NoChildren

    private(*NoChildren::NAMES)
  end

  def self.guard
    Kernel.singleton_class.prepend(NoChildren)
    Process.singleton_class.prepend(NoChildren)
    Object.prepend(PrivateNoChildren)
  end
end

UnitLayer.guard

RSpec.configure do |config|
  config.expect_with(:rspec) { |c| c.syntax = :expect }
  config.disable_monkey_patching!
  config.order = :random

  config.around(:each, file_path: %r{spec/unit/}) do |example|
    Thread.current[:relspec_unit] = true
    example.run
  ensure
    Thread.current[:relspec_unit] = nil
  end

  # `RSpec.describe X, :tmpdir`: each example gets an empty folder in @dir,
  # for the few core files whose input is a folder (a cache, an overlay).
  # (spec_helper's hook of the same name gives one when both are loaded.)
  config.around(:each, :tmpdir) do |example|
    next example.run if @dir

    Dir.mktmpdir("relspec-unit") do |dir|
      @dir = dir
      example.run
    end
  end
end

require "relspec/release_specs/spec_file"

# Release-spec files from text, as SpecFile reads them from disk.
module SpecFiles
  def spec_file(text, name: "child")
    path = "specs/#{name}.yml"
    Relspec::ReleaseSpec::SpecFile.new(path, Relspec::Yaml::LocatedDocument.parse(text, file: path))
  end

  # "rule@line: message" of each diagnostic, in reading order.
  def findings(diagnostics)
    diagnostics.sort_by(&:sort_key).map { |d| "#{d.severity} #{d.rule}@#{d.location&.line}: #{d.message}" }
  end
end

RSpec.configure { |config| config.include SpecFiles, file_path: %r{spec/unit/release_specs/} }

require "relspec/catalog/package"
require "relspec/debian/build_input"

# The input of one package's debian/ (Debian::BuildInput), in memory: a
# catalog package of +build_type+ whose fields +package+ overrides, and the
# input's own fields from +fields+.
module BuildInputs
  def build_input(build_type: "cmake", package: {}, **fields)
    catalog_package = Relspec::Catalog::Package.new(
      name: "pkg", package_set: "set", build_type: build_type, commit_time: "2021-03-04T05:06:07Z", source_dir: "src/pkg",
      vcs: Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "https://example.org/pkg.git", "commit" => "a" * 40),
      **package
    )
    Relspec::Debian::BuildInput.new(
      package: catalog_package, deb_name: "rock-r-pkg", upstream: "0.1", codename: "bookworm", release: "r",
      maintainer: "M <m@example.org>", install_dir: "/opt/rock/r/rock-r-pkg", dependencies: [], apt: [], gems: [],
      gem: nil, **fields
    )
  end

  def dependency(deb_name, install_dir)
    Relspec::Debian::BuildInput::Dependency.new(deb_name: deb_name, version: "1.0-1", install_dir: install_dir)
  end
end

RSpec.configure { |config| config.include BuildInputs, file_path: %r{spec/unit/debian/} }
