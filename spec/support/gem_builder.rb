# frozen_string_literal: true

require "open3"
require "tmpdir"
require "fileutils"

# Builds real .gem files with `gem build`, dated by SOURCE_DATE_EPOCH so the
# same call gives the same bytes. The gems are stand-ins: small, but named
# like the gems the demo workspace's osdeps name (nokogiri) so that the
# workspace's packages depend on them.
module GemBuilder
  module_function

  # Writes <name>-<version>.gem into +dir+. +dependencies+: name =>
  # requirement; +executable+: a bin/ script; +extension+: a C extension
  # built by `gem install` (needs ruby-dev), whose extconf.rb requires the
  # gems named in +extension+ if it is a list; +files+: more files;
  # +ruby+: its required_ruby_version (">= 3.2").
  def build(dir, name, version, dependencies: {}, executable: false, extension: false, date: "2020-02-02", files: {}, ruby: nil)
    Dir.mktmpdir("relspec-gem-src") do |src|
      files = files.merge("lib/#{name}.rb" => "module #{name.split(/[_-]/).map(&:capitalize).join}\n  VERSION = #{version.inspect}\nend\n")
      files["bin/#{name}"] = "#!/usr/bin/env ruby\nputs #{name.inspect}\n" if executable
      if extension
        requires = Array(extension == true ? [] : extension).map { |gem| "require #{gem.inspect}\n" }.join
        files["ext/#{name}/extconf.rb"] = "#{requires}require \"mkmf\"\ncreate_makefile(\"#{name}/#{name}_ext\")\n"
        files["ext/#{name}/#{name}_ext.c"] = "#include <ruby.h>\nvoid Init_#{name}_ext(void) { rb_define_module(\"#{name.capitalize}Ext\"); }\n"
      end
      files.each do |path, content|
        FileUtils.mkdir_p(File.join(src, File.dirname(path)))
        File.write(File.join(src, path), content)
      end
      File.write(File.join(src, "#{name}.gemspec"), gemspec(name, version, files.keys, dependencies, executable, extension, ruby))
      epoch = Time.utc(*date.split("-").map(&:to_i)).to_i.to_s
      output, status = Open3.capture2e({ "SOURCE_DATE_EPOCH" => epoch }, "gem", "build", "#{name}.gemspec", chdir: src)
      raise "gem build #{name} failed: #{output}" unless status.success?

      FileUtils.mkdir_p(dir)
      FileUtils.mv(File.join(src, "#{name}-#{version}.gem"), File.join(dir, "#{name}-#{version}.gem"))
    end
    File.join(dir, "#{name}-#{version}.gem")
  end

  # Writes the compact index rubygems.org serves to Bundler,
  # <root>/info/<name> (one line per version: "1.0.0 dep:>= 1|checksum:…",
  # with ",ruby:>= 3.2" when the gem needs a Ruby),
  # for every .gem in <root>/gems, so a test server lists versions as
  # rubygems.org does. Returns the names indexed.
  def compact_index(root)
    require "digest"
    require "rubygems/package"
    gems = Dir.glob(File.join(root, "gems", "*.gem")).sort.map { |path| [Gem::Package.new(path).spec, path] }
    FileUtils.mkdir_p(File.join(root, "info"))
    gems.group_by { |spec, _| spec.name }.each do |name, entries|
      lines = entries.sort_by { |spec, _| spec.version }.map do |spec, path|
        dependencies = spec.runtime_dependencies.map { |dependency| "#{dependency.name}:#{dependency.requirement}" }.join(",")
        ruby = ",ruby:#{spec.required_ruby_version.as_list.join('&')}" unless spec.required_ruby_version.none?
        "#{spec.version} #{dependencies}|checksum:#{Digest::SHA256.file(path).hexdigest}#{ruby}\n"
      end
      File.write(File.join(root, "info", name), "---\n#{lines.join}")
    end.keys
  end

  def gemspec(name, version, files, dependencies, executable, extension, ruby = nil)
    lines = [
      "s.name = #{name.inspect}", "s.version = #{version.inspect}", "s.summary = \"Stand-in #{name} gem\"",
      "s.description = \"A small #{name} gem built by the relspec tests.\"", "s.authors = [\"Relspec Tests\"]",
      "s.license = \"MIT\"", "s.homepage = \"https://example.org/#{name}\"", "s.files = #{files.inspect}"
    ]
    lines << "s.executables = [#{name.inspect}]" if executable
    lines << "s.extensions = [\"ext/#{name}/extconf.rb\"]" if extension
    lines << "s.required_ruby_version = #{ruby.inspect}" if ruby
    dependencies.each { |dependency, requirement| lines << "s.add_runtime_dependency #{dependency.inspect}, #{requirement.inspect}" }
    "Gem::Specification.new do |s|\n#{lines.map { |line| "  #{line}\n" }.join}end\n"
  end
end
