# frozen_string_literal: true

require "spec_helper"
require "tmpdir"
require "open3"
require "relspec/debian/debian_dir"
require "relspec/catalog/package"

# The words debian/rules gives CMake and oroGen come from the package sets
# (pkg.define, orogen_options): each must reach the tool as one word, as
# written, whatever it holds. Checked by asking make itself (make -n prints
# the shell line) and a shell to split that line.
RSpec.describe "debian/rules words from the package sets" do
  def rules(build_type, defines: {}, orogen_arguments: [])
    package = Relspec::Catalog::Package.new(
      name: "pkg", package_set: "set", build_type: build_type, commit_time: "2021-03-04T05:06:07Z",
      source_dir: "src/pkg", orogen_arguments: orogen_arguments,
      vcs: Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "https://example.org/pkg.git", "commit" => "a" * 40)
    )
    input = Relspec::Debian::BuildInput.new(
      package: package, deb_name: "rock-r-pkg", upstream: "0.1", codename: "bookworm", release: "r",
      maintainer: "M <m@example.org>", install_dir: "/opt/rock/r/rock-r-pkg", dependencies: [], apt: [],
      gems: [], gem: nil, debhelper_compat: 13, defines: defines
    )
    Relspec::Debian::DebianDir.render(input, version: "0.1-1~bookworm").fetch("rules").first
  end

  # The words the shell gives the command make runs for +target+ (one line
  # starting with +command+), from the rules file alone.
  def words_of(rules_text, target, command)
    Dir.mktmpdir("relspec-rules") do |dir|
      File.write(File.join(dir, "rules"), rules_text)
      File.write(File.join(dir, "std.orogen"), "name 'std'\n")
      lines, status = Open3.capture2e("make", "-n", "-f", "rules", target, chdir: dir)
      expect(status).to be_success, lines
      line = lines.lines.find { |l| l.start_with?(command) } or raise "no #{command} line in:\n#{lines}"
      out, status = Open3.capture2("sh", "-c", "for w in #{line.chomp}; do printf '%s\\n' \"$w\"; done")
      expect(status).to be_success
      out.lines(chomp: true)
    end
  end

  it "gives oroGen the words autoproj gives it, in order, the .orogen file last" do
    words = %w[--corba --import=std --no-rtt-scripting --transports=corba,mqueue,typelib --type-export-policy=used std.orogen]
    expect(words_of(rules("orogen", orogen_arguments: words), "override_dh_auto_configure", "orogen"))
      .to eq(["orogen"] + words)
  end

  it "names the .orogen file of the source when the words do not (a snapshot without them)" do
    expect(words_of(rules("orogen"), "override_dh_auto_configure", "orogen"))
      .to eq(%w[orogen --corba --transports=corba,mqueue,typelib --type-export-policy=used std.orogen])
  end

  it "keeps a word with spaces, quotes or $ as one word, unexpanded" do
    odd = ["--import=a b", "--x=it's", "--y=$(id) $HOME"]
    expect(words_of(rules("orogen", orogen_arguments: odd + ["std.orogen"]), "override_dh_auto_configure", "orogen"))
      .to eq(["orogen", *odd, "std.orogen"])
    cmake = words_of(rules("cmake", defines: { "A" => "$(id)", "B" => "x y" }), "override_dh_auto_configure", "dh_auto_configure")
    expect(cmake).to include("-DA=$(id)", "-DB=x y", "-DCMAKE_INSTALL_PREFIX=/opt/rock/r/rock-r-pkg")
  end
end
