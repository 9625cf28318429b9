# frozen_string_literal: true

require "fileutils"

# Writes release spec hierarchies into temporary folders for tests.
module SpecWriter
  # Yields a specs/ folder holding +files+ (release name => YAML text).
  def with_specs(files)
    Dir.mktmpdir("relspec-specs") do |root|
      dir = File.join(root, "specs")
      FileUtils.mkdir_p(dir)
      files.each { |name, text| File.write(File.join(dir, "#{name}.yml"), text) }
      yield dir, root
    end
  end

  def resolve(dir, name)
    library = Relspec::ReleaseSpec::Library.new(dir)
    Relspec::ReleaseSpec::Resolution.of(library, library.path_for(name))
  end
end
