# frozen_string_literal: true

module Relspec
  module ReleaseSpec
    # The built-in value of every inherited key a spec may leave out: the one
    # place a default is written (inheritance applies them, the typed values
    # and external releases fall back to them).
    DEFAULTS = {
      "install_prefix" => "/opt/rock", "separate_prefixes" => true, "package_prefix" => "rock",
      "gems" => {}, "distributions" => {}, "gem_source" => "https://rubygems.org"
    }.freeze
  end
end
