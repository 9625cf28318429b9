# frozen_string_literal: true

require_relative "real_rock_workspace"

# RealRockWorkspace with SISL checked out too, so that base/types is built as
# the real package sets build it (USE_SISL on, its spline bindings with it)
# and base/orogen/types, whose typekit wraps base/geometry/Spline and names
# SISL as a hard dependency, is in reach. bin/toolchain-acceptance's
# workspace: the toolchain with the typekit of /base/samples/RigidBodyState.
# CI's toolchain test keeps RealRockWorkspace (SISL and base/orogen/types
# would add their builds to its critical path).
class RealRockSislWorkspace < RealRockWorkspace
  PACKAGES = RealRockWorkspace::PACKAGES.merge("external/sisl" => ["external-sisl", "external/sisl"]).freeze

  private

  # SISL is there: base/types needs no word from the workspace.
  def setup_overrides; end
end
