# frozen_string_literal: true

require "spec_helper"
require "relspec/debian/debian_dir"
require "relspec/catalog/package"
require "relspec/catalog/copyright_holders"

# debian/copyright and the changelog of a workspace package, rendered the
# way compile renders them (DebianDir), and checked by Debian's own DEP-5
# parser (python3-debian's debian.copyright, which lintian's checks follow).
RSpec.describe "debian/copyright of a Rock package" do
  def package(**changes)
    Relspec::Catalog::Package.new(
      name: "base/cmake", package_set: "rock.core", build_type: "cmake",
      vcs: Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "$AUTOPROJ_ROOT/repositories/base/cmake.git",
                                        "branch" => "master", "commit" => "a" * 40),
      commit_time: "2021-03-04T05:06:07Z", source_dir: "src/base/cmake", license: "LGPL v2 or later",
      maintainer: "Sylvain Joyeux <sylvain.joyeux@m4x.org>",
      copyright: ["DFKI <robotik@dfki.de>", "Sylvain Joyeux <sylvain.joyeux@m4x.org>"], **changes
    )
  end

  def render(package)
    input = Relspec::Debian::BuildInput.new(
      package: package, deb_name: "rock-r-base-cmake", upstream: "0.20210304.050607", codename: "bookworm",
      release: "r", maintainer: "Release Maintainer <release@example.org>",
      install_dir: "/opt/rock/r/rock-r-base-cmake", dependencies: [], apt: [], gems: [], gem: nil
    )
    Relspec::Debian::DebianDir.render(input, version: "0.20210304.050607-1~bookworm").transform_values(&:first)
  end

  def parsed(copyright)
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "copyright"), copyright)
      script = "import sys; from debian.copyright import Copyright; c = Copyright(open(sys.argv[1])); " \
               "p = list(c.all_files_paragraphs())[0]; print(' | '.join(l.strip() for l in p.copyright.splitlines())); print(p.license.synopsis); " \
               "print(c.header.upstream_name); print(c.header.source)"
      output, status = Open3.capture2e("/usr/bin/python3", "-c", script, File.join(dir, "copyright"))
      raise output unless status.success?

      output.lines.map(&:chomp)
    end
  end

  it "names the upstream holders and a DEP-5 short name, and keeps the manifest's text" do
    copyright = render(package)["copyright"]
    holders, license, name, source = parsed(copyright)
    expect(holders).to eq("DFKI <robotik@dfki.de> | Sylvain Joyeux <sylvain.joyeux@m4x.org>")
    expect(license).to eq("LGPL-2+")
    expect(name).to eq("base/cmake")
    expect(source).to eq("None") # a repository of the workspace is no public source
    expect(copyright).to include("declares its license as: LGPL v2 or later")
    expect(copyright).to include("/usr/share/common-licenses/LGPL-2")
    expect(copyright).not_to include("release@example.org")
  end

  it "falls back to the manifest's authors or maintainers, never the release maintainer" do
    holders, = parsed(render(package(copyright: []))["copyright"])
    expect(holders).to eq("Sylvain Joyeux <sylvain.joyeux@m4x.org>")
    holders, = parsed(render(package(copyright: [], maintainer: nil))["copyright"])
    expect(holders).to eq("the authors of base/cmake")
  end

  it "writes no unexpanded $AUTOPROJ_ROOT, and a public URL as the Source" do
    files = render(package)
    expect(files["changelog"]).not_to include("$AUTOPROJ_ROOT")
    expect(files["changelog"]).to include("  * Release r: base/cmake\n    from the autoproj workspace's repositories/base/cmake.git\n")
    # (each line within lintian's 80 columns: debian-changelog-line-too-long)
    expect(files["changelog"].lines.map { |line| line.chomp.length }.max).to be <= 80
    public = package(vcs: Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "https://github.com/rock-core/base-cmake.git",
                                                       "commit" => "a" * 40))
    expect(parsed(render(public)["copyright"]).last).to eq("https://github.com/rock-core/base-cmake.git")
  end

  {
    "LGPL v2 or later" => "LGPL-2+", "LGPLv2.1 or later" => "LGPL-2.1+", "LGPL v3" => "LGPL-3",
    "GPL v2 or later" => "GPL-2+", "New BSD License" => "BSD-3-clause", "BSD" => "BSD-3-clause",
    "MIT" => "Expat", "Apache License 2.0" => "Apache-2.0", "CeCILL-B (BSD-like)" => "CeCILL-B",
    "Ruby" => "Ruby", "some custom terms" => "other", "" => "other"
  }.each do |text, short|
    it "maps the license text #{text.inspect} to #{short}" do
      expect(Relspec::Debian::LicenseName.of(text)).to eq(short)
    end
  end

  it "reads holders from manifest.xml's <copyright>, one a line as Name/email" do
    Dir.mktmpdir do |dir|
      path = File.join(dir, "manifest.xml")
      File.write(path, "<package>\n  <copyright>\n    DFKI/robotik@dfki.de\n    Jane Doe\n  </copyright>\n</package>\n")
      expect(Relspec::Catalog::CopyrightHolders.of(path, [["A", "a@x"]], [])).to eq(["DFKI <robotik@dfki.de>", "Jane Doe"])
      File.write(path, "<package><author>A/a@x</author></package>")
      expect(Relspec::Catalog::CopyrightHolders.of(path, [["A", "a@x"]], [["M", nil]])).to eq(["A <a@x>"])
      expect(Relspec::Catalog::CopyrightHolders.of(path, [], [["M", nil]])).to eq(["M"])
    end
  end
end
