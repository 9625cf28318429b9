# frozen_string_literal: true

require "spec_helper"
require "open3"
require "relspec/osdeps/package_set"

# The relspec code a package set ships runs in a user's workspace without
# relspec installed: init.rb's require_relative lines must find every file
# they pull in inside the package set. A require added to a shipped file
# (diagnostic.rb, by package_pattern.rb) once broke every autoproj command
# of a workspace using the package set; this loads the shipped code alone,
# in a Ruby that has neither relspec's lib/ nor its bundle.
RSpec.describe "the relspec code a package set ships", :tmpdir do
  let(:package_set) { Relspec::Osdeps::PackageSet }

  it "holds the require_relative closure of init.rb, so the selection loads without relspec" do
    package_set.shipped.each do |path|
      FileUtils.mkdir_p(File.dirname(File.join(@dir, "lib", path)))
      FileUtils.cp(File.join(package_set::LIB, path), File.join(@dir, "lib", path))
    end
    requires = File.read(package_set::INIT).scan(/^require_relative "[^"]+"$/).join("\n")
    File.write(File.join(@dir, "load.rb"), "#{requires}\nputs Relspec::Osdeps::Selection.name\n")

    output, status = Open3.capture2e({ "RUBYOPT" => nil, "BUNDLE_GEMFILE" => nil }, "ruby", "--disable-gems",
                                     File.join(@dir, "load.rb"), unsetenv_others: false)
    expect(status.success?).to be(true), output
    expect(output).to eq("Relspec::Osdeps::Selection\n")
    expect(package_set.shipped).to include("relspec/diagnostic.rb", "relspec/osdeps/selection.rb")
  end
end
