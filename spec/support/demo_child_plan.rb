# frozen_string_literal: true

require "fileutils"

# The plan.yml a last build of demo-child's base/types was made from, for
# tests that write that build's results by hand: the records of a build
# are taken at its plan's versions (TargetBuild), so results need the plan.
module DemoChildPlan
  SOURCE = "rock-demo-child-base-types"
  VERSION = "2.0-1~bookworm"

  # Writes <target>/plan.yml (+target+: demo-child's bookworm-amd64 folder).
  def self.write(target)
    FileUtils.mkdir_p(target)
    File.write(File.join(target, "plan.yml"), <<~YAML)
      release: demo-child
      target: bookworm/amd64
      builds:
        - { package: base/types, source: #{SOURCE}, version: #{VERSION}, dsc: #{SOURCE}/#{SOURCE}_#{VERSION}.dsc, build_depends: [] }
    YAML
  end
end
