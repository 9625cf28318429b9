# frozen_string_literal: true

require_relative "release_specs/library"
require_relative "release_specs/resolution"
require_relative "error"

module Relspec
  # Release specs: reading, checking and inheriting them (docs/spec-reference.md).
  module ReleaseSpec
    # The effective spec of the release in +path+, whose parents are looked
    # up beside it; raises InvalidInput with every error found.
    def self.resolve(path)
      resolution = Resolution.of(Library.new(File.dirname(path)), path)
      raise InvalidInput, resolution.errors unless resolution.ok?

      resolution
    end
  end
end
