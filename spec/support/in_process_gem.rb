# frozen_string_literal: true

require "fileutils"
require "rubygems/package"

# A real .gem file written in-process (Gem::Package, no `gem build` child:
# what the unit layer can use), dated 2020-02-02.
module InProcessGem
  module_function

  # Writes <dir>/<name>-<version>.gem and returns its path. +dependencies+:
  # name => requirement; +ruby+: its required_ruby_version.
  def write(dir, name, version, dependencies: {}, ruby: nil)
    spec = Gem::Specification.new do |gem|
      gem.name = name
      gem.version = version
      gem.summary = "#{name} stand-in"
      gem.authors = ["Demo"]
      gem.files = []
      gem.date = Time.utc(2020, 2, 2)
      gem.required_ruby_version = ruby if ruby
      dependencies.each { |other, requirement| gem.add_runtime_dependency(other, requirement) }
    end
    FileUtils.mkdir_p(dir)
    path = File.join(dir, "#{name}-#{version}.gem")
    package = Gem::Package.new(path)
    package.spec = spec
    Gem::DefaultUserInteraction.use_ui(Gem::SilentUI.new) { package.build }
    path
  end
end
