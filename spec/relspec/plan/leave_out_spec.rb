# frozen_string_literal: true

require "spec_helper"
require_relative "../../support/real_rock_workspace"
require_relative "../../support/gem_builder"

# `leave_out` on the real layout (rock.core + orocos.toolchain, layout
# rock.core as in rock-core/buildconf): the qt4 packages cannot exist on
# bookworm, so a maintainer leaves them out with the reason; what requires
# them is left out too, an optional dependency on them is dropped, and
# plan, why and check see the rest. ../shared bundles only the toolchain's
# repositories: the packages it lacks are left out as well, which is also
# what a maintainer does with a package not ready for a release.
RSpec.describe "leave_out on the real Rock layout" do
  qt4 = %w[gui/qtpropertybrowser gui/rock_widget_collection gui/vizkit3d].freeze
  qt4_match = '/\Agui\/(qtpropertybrowser|rock_widget_collection|vizkit3d)\z/'

  not_bundled = %w[
    base/console_bridge base/scripts base/templates/** bundles/** drivers/** external/sisl gui/osgviz gui/rock_webapp gui/vizkit
    perception/** tools/class_loader tools/log_tools tools/logger tools/msgpack-c tools/pocolog tools/pocolog2msgpack
    tools/pocolog_cpp tools/rest_api tools/roby tools/syskit tools/telemetry
  ].freeze

  before(:all) do
    need_fixture(RealRockWorkspace.available?, RealRockWorkspace.skip_reason)
    @workspace = RealRockWorkspace.shared
    @dir = Dir.mktmpdir("relspec-leave-out")
    # stand-ins at the versions Rock's osdeps ask for (rice<4.0.0,
    # rake-compiler<0.9.0) and facets, which bookworm lacks
    { "facets" => "3.1.0", "rice" => "3.0.0", "rake-compiler" => "0.8.3" }.each do |name, version|
      GemBuilder.build(File.join(@dir, "gems"), name, version)
    end
    left_out = not_bundled.map { |match| "  - { match: #{match}, reason: not among the repositories of ../shared }\n" }.join
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "rock.yml"), <<~YAML)
      release: rock
      workspace: #{@workspace.root}
      targets: { bookworm: [amd64] }
      distributions: { bookworm: { archive: { host: true } } }
      gem_source: ../gems
      leave_out:
        - match: #{qt4_match}
          reason: needs qt4, which bookworm lacks
          targets: [bookworm]
      #{left_out}
    YAML
  end

  after(:all) { FileUtils.rm_rf(@dir) if @dir }

  it "plans the layout without what bookworm lacks, and says what was left out and why" do
    run = relspec("plan", "specs/rock.yml", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    gaps = run.stdout[%r{^not available on bookworm/amd64:\n(.*?)\n\n}m, 1]
    qt4.each do |name|
      line = gaps.lines.find { |entry| entry.start_with?("  #{name} ") }
      expect(line).to end_with(%(left out by "#{qt4_match}" (needs qt4, which bookworm lacks)\n))
    end
    # base/orogen/types requires external/sisl: left out with it
    expect(gaps).to include(%(  base/orogen/types                   depends on external/sisl, which is unavailable because ) +
                            %(left out by "external/sisl" (not among the repositories of ../shared)\n))
    built = run.stdout[%r{^builds on bookworm/amd64:\n(.*?)\n\n}m, 1].lines.grep(/^  \S/).map { |line| line.split.first }
    # base/types and tools/orocos.rb only optionally depend on gui/vizkit3d and tools/pocolog: built without them
    expect(built).to include("typelib", "rtt", "rtt_typelib", "orogen", "base/orogen/std", "base/types", "tools/orocos.rb")
    expect(built & (qt4 + %w[base/orogen/types external/sisl tools/pocolog])).to eq([])
    # and plan says so, as it does for an optional osdep the distribution lacks
    expect(run.stdout).to include(%(base/types is built without its optional dependency gui/vizkit3d on bookworm: it is ) +
                                  %(unavailable there (left out by "#{qt4_match}" (needs qt4, which bookworm lacks))))
  end

  it "explains one left-out package with `why`" do
    run = relspec("why", "specs/rock.yml", "gui/vizkit3d", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("bookworm/amd64: gui/vizkit3d cannot be built there, because:")
      .and include(%(left out by "#{qt4_match}" (needs qt4, which bookworm lacks)))
  end

  it "passes `check`: no relation of what is left needs qt4" do
    run = relspec("check", "specs/rock.yml", chdir: @dir)
    expect([run.exit_code, run.stderr.lines.grep(/error/)]).to eq([0, []])
    expect(run.stdout).to match(%r{\Abookworm/amd64: \d+ relations checked})
  end

  it "shows in `relspec diff` what a new entry leaves out and why" do
    changed = File.join(@dir, "changed", "specs")
    FileUtils.mkdir_p(changed)
    spec = File.read(File.join(@dir, "specs", "rock.yml")).sub("gem_source: ../gems", "gem_source: #{@dir}/gems")
    File.write(File.join(changed, "rock.yml"), "#{spec}  - match: tools/orocos.rb\n    reason: its CORBA transport is not built yet\n")
    run = relspec("diff", "specs/rock.yml", "changed/specs/rock.yml", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("spec: leave_out entry tools/orocos.rb added (its CORBA transport is not built yet) " \
                                  "→ 1 decision (bookworm/amd64)")
    change = run.stdout[%r{^ +decision changed +tools/orocos\.rb: .*\n.*\n}]
    expect(change).to match(/build rock-rock-ruby-tools-orocos\.rb \S+ → unavailable\n/)
    expect(change.lines.last.strip).to eq('left out by "tools/orocos.rb" (its CORBA transport is not built yet)')
  end

  it "refuses an entry that matches no package of the workspace" do
    spec = File.read(File.join(@dir, "specs", "rock.yml")).sub("match: drivers/**", "match: driver/**")
    File.write(File.join(@dir, "specs", "typo.yml"), spec.sub("release: rock", "release: typo"))
    run = relspec("plan", "specs/typo.yml", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to match(%r{specs/typo\.yml:\d+:\d+: error\[unmatched-leave-out\]: leave_out entry "driver/\*\*" matches no package})
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
  end
end
