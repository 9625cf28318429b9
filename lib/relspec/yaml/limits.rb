# frozen_string_literal: true

module Relspec
  module Yaml
    # Bounds on every YAML file relspec reads (specs, locks, snapshots,
    # blacklists): files come from many people, and an 833-byte alias bomb or
    # 3,000 nested brackets must be refused in well under a second, not eat
    # memory or the stack. docs/limits.md gives the reason for each value.
    module Limits
      # The largest catalog snapshot of a full Rock release is below 2 MiB;
      # 16 MiB leaves room for ten times that while the node tree Psych builds
      # (about 30 bytes of memory per byte of YAML) stays under 500 MB.
      MAX_BYTES = 16 * 1024 * 1024
      # Specs nest 4 levels, snapshots 6; nothing a person writes needs 64.
      # Deeper trees would overflow the stack of the recursive readers.
      MAX_DEPTH = 64
      # Values copied in by aliases (`*name`), counted as the nodes they
      # stand for: shared target lists use a few hundred; a bomb 10^7.
      MAX_ALIAS_NODES = 10_000
    end
  end
end
