# frozen_string_literal: true

require_relative "../unit_helper"
require "autobuild"
require "relspec/catalog/ruby_extension"
require "relspec/catalog/package"
require "relspec/debian/debian_dir"

# A Ruby package that compiles a C extension (tools/orocos.rb's rorocos)
# gets autoproj's setup task run in its build, and is architecture-dependent;
# a pure-Ruby one does not (its "default" task is often its tests).
RSpec.describe Relspec::Catalog::RubyExtension, :tmpdir do
  # a checkout of its own each time (a folder below the example's)
  def ruby_package(files)
    srcdir = Dir.mktmpdir("checkout", @dir)
    files.each do |path, content|
      FileUtils.mkdir_p(File.dirname(File.join(srcdir, path)))
      File.write(File.join(srcdir, path), content)
    end
    Autobuild::Ruby.new("tools/#{File.basename(srcdir)}").tap { |pkg| pkg.srcdir = srcdir }
  end

  it "gives autoproj's setup task of a package with an extension" do
    package = ruby_package("Rakefile" => "", "ext/rorocos/extconf.rb" => "")
    expect(described_class.setup_task(package)).to eq("default")
    package.rake_setup_task = "setup"
    expect(described_class.setup_task(package)).to eq("setup")
  end

  it "gives none without an extension, without a Rakefile, without a task or for a task a shell would read" do
    expect(described_class.setup_task(ruby_package("Rakefile" => "", "lib/x.rb" => ""))).to be_nil
    expect(described_class.setup_task(ruby_package("ext/x/extconf.rb" => ""))).to be_nil
    package = ruby_package("Rakefile" => "", "ext/x/extconf.rb" => "")
    package.rake_setup_task = nil
    expect(described_class.setup_task(package)).to be_nil
    package.rake_setup_task = "default; rm -rf /"
    expect(described_class.setup_task(package)).to be_nil
  end

  describe "in debian/" do
    def render(extension_task)
      package = Relspec::Catalog::Package.new(
        name: "tools/orocos.rb", package_set: "set", build_type: "ruby", commit_time: "2021-03-04T05:06:07Z",
        source_dir: "tools/orocos.rb", extension_task: extension_task,
        vcs: Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "https://example.org/o.git", "commit" => "a" * 40)
      )
      input = Relspec::Debian::BuildInput.new(
        package: package, deb_name: "rock-r-tools-orocos.rb", upstream: "0.1", codename: "bookworm", release: "r",
        maintainer: "M <m@example.org>", install_dir: "/opt/rock/r/rock-r-tools-orocos.rb", dependencies: [], apt: [],
        gems: [], gem: nil, extension_task: Relspec::Catalog::RubyExtension.checked(package)
      )
      Relspec::Debian::DebianDir.render(input, version: "0.1-1~bookworm").transform_values(&:first)
    end

    it "runs the task, installs the compiled .so and is architecture-dependent" do
      files = render("default")
      expect(files["rules"]).to include("override_dh_auto_build:\n\trake default\n")
      expect(files["rules"]).to include("find . -name '*.so' -exec install -D -m 0644")
      expect(files["control"]).to match(/^Architecture: any$/).and include("${shlibs:Depends}")
      expect(files["control"][/^Build-Depends:(.*?)^(?=\S)/m, 1]).to include("ruby-dev")
    end

    it "leaves a pure-Ruby package alone" do
      files = render(nil)
      expect(files["rules"]).not_to include("rake ")
      expect(files["control"]).to match(/^Architecture: all$/)
    end

    it "refuses a task a shell would read, from a catalog written by hand" do
      expect { render("x;y") }.to raise_error(ArgumentError, /bad rake task "x;y"/)
    end
  end
end
