# frozen_string_literal: true

require_relative "relspec/version"
require_relative "relspec/error"
require_relative "relspec/release_specs"
