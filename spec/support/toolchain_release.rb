# frozen_string_literal: true

require "fileutils"
require_relative "real_rock_workspace"
require_relative "real_rock_sisl_workspace"
require_relative "rock_gems"

# The Rock toolchain as a release maintainer would package it from the REAL
# package sets (rock.core + orocos.toolchain, RealRockWorkspace): a release
# spec selecting some packages of the layout, the real gems bookworm lacks
# (RockGems) in gem_source, the project's overlays, and leave_out for what
# a maintainer would leave out here: qt4's packages (bookworm has no qt4)
# and the packages ../shared has no repository for. Shared by bin/toolchain
# and spec/toolchain/.
#
#   release = ToolchainRelease.new(dir, select: %w[base/orogen/std base/types])
#   release.write  # dir/specs/rock.yml, dir/gems, dir/overlays (and dir/workspace once)
#
# With sisl: true the workspace has SISL (RealRockSislWorkspace), base/types
# is built with it and base/orogen/types can be selected (TYPES_SELECTION).
class ToolchainRelease
  ROOT = File.expand_path("../..", __dir__)

  # What the acceptance needs: oroGen's chain up to base/orogen/std, and
  # base/types for the user's component.
  DEFAULT_SELECTION = %w[base/orogen/std base/types].freeze
  # ... and the typekit of the types every component uses (needs sisl: true)
  TYPES_SELECTION = (DEFAULT_SELECTION + %w[base/orogen/types]).freeze

  # Packages of the layout the workspace does not check out (it clones only
  # RealRockWorkspace::PACKAGES from ../shared). external/sisl among them
  # keeps base/orogen/types out: it names SISL as a hard dependency (its
  # typekit wraps base/geometry/Spline); with sisl: true SISL is in.
  NOT_BUNDLED = %w[
    base/console_bridge base/scripts base/templates/** bundles/** drivers/** external/sisl gui/osgviz gui/rock_webapp
    gui/vizkit perception/** tools/class_loader tools/log_tools tools/logger tools/msgpack-c tools/pocolog
    tools/pocolog2msgpack tools/pocolog_cpp tools/rest_api tools/roby tools/syskit tools/telemetry
  ].freeze
  QT4 = '/\Agui\/(qtpropertybrowser|rock_widget_collection|vizkit3d)\z/'
  # the real gems at the versions Rock's osdeps ask for, which bookworm lacks
  GEMS = { "facets" => "3.1.0", "rice" => "3.0.0", "rake-compiler" => "0.8.3" }.freeze

  attr_reader :dir, :selection

  def initialize(dir, select: DEFAULT_SELECTION, sisl: false)
    @dir = dir
    @selection = select
    @sisl = sisl
  end

  def spec_path
    File.join(dir, "specs", "rock.yml")
  end

  def target_dir
    File.join(dir, "out", "rock", "bookworm-amd64")
  end

  def workspace
    @workspace ||= (@sisl ? RealRockSislWorkspace : RealRockWorkspace).new(dir)
  end

  # Writes what `relspec compile` needs; the workspace only when it is not
  # there yet (a second run rebuilds only what changed). Raises when a gem
  # can be neither found nor fetched, or when dir's workspace was made
  # without a package this release needs (SISL).
  def write
    workspace.create unless File.directory?(workspace.root)
    raise "#{workspace.root} was made without some of this release's packages: remove it" unless workspace.complete?

    GEMS.each do |name, version|
      next if RockGems.provide(File.join(dir, "gems"), name, version)

      raise "#{name}-#{version}.gem is neither in #{RockGems::CACHE} nor fetchable from #{Gem.sources.first}"
    end
    # the project's overlays (upstream bugs patched for this release), as
    # they are, and (without SISL) the one building base/types without it needs
    FileUtils.rm_rf(File.join(dir, "overlays"))
    FileUtils.cp_r(File.join(ROOT, "overlays"), dir)
    FileUtils.cp_r(File.join(ROOT, "spec", "fixtures", "toolchain_overlays", "."), File.join(dir, "overlays")) unless @sisl
    FileUtils.mkdir_p(File.dirname(spec_path))
    File.write(spec_path, spec_text)
  end

  def spec_text
    not_here = @sisl ? NOT_BUNDLED - %w[external/sisl] : NOT_BUNDLED
    left_out = not_here.map { |match| "  - { match: #{match}, reason: not among the repositories of ../shared }\n" }.join
    <<~YAML
      release: rock
      maintainer: relspec toolchain <toolchain@relspec.invalid>
      workspace: ../workspace
      select: [#{selection.join(', ')}]
      targets: { bookworm: [amd64] }
      distributions: { bookworm: { archive: { host: true } } }
      gem_source: ../gems
      leave_out:
        - { match: '#{QT4}', reason: "needs qt4, which bookworm lacks", targets: [bookworm] }
      #{left_out}
    YAML
  end
end
