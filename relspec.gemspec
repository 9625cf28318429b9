# frozen_string_literal: true

require_relative "lib/relspec/version"

Gem::Specification.new do |s|
  s.name = "relspec"
  s.version = Relspec::VERSION
  s.summary = "Declarative release-spec compiler for autoproj-based Debian releases"
  s.description = <<~TEXT
    relspec validates release specs (parent releases, blacklists, pins, targets),
    reads the package database of an autoproj workspace and the ancestor releases'
    apt repositories, and emits only the missing Debian source packages plus the
    autoproj osdeps files that let a workspace use the binaries.
  TEXT
  s.authors = ["relspec developers"]
  s.license = "BSD-3-Clause"
  s.required_ruby_version = ">= 3.1"
  s.files = Dir["lib/**/*", "exe/*", "README.md", "docs/**/*"]
  s.bindir = "exe"
  s.executables = ["relspec"]
  s.require_paths = ["lib"]

  s.add_dependency "autoproj", "~> 2.18"
  s.add_dependency "dry-schema", "~> 1.13.4"
  s.add_dependency "thor", "~> 1.3"
  s.add_dependency "tty-progressbar", "~> 0.18"
end
