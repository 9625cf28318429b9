# frozen_string_literal: true

require "spec_helper"
require "digest"

# Compile output depends on its inputs only: not on the umask, the time zone
# or the language of the person running it.
RSpec.describe "compile output under different environments" do
  it "is byte-identical under umask 022, 077 and 002, another TZ and another LANG" do
    Dir.mktmpdir("relspec-env") do |dir|
      fixture = ReleaseFixture.new(dir)
      fixture.standalone("rel", select: %w[base/logging tools/orocos.rb], targets: "bionic: [amd64]")
      FileUtils.mkdir_p(File.join(dir, "overlays", "base", "logging", "files", "extra"))
      File.write(File.join(dir, "overlays", "base", "logging", "files", "extra", "NOTE"), "overlay\n")
      runs = {
        "umask022" => [0o022, {}], "umask077" => [0o077, {}], "umask002" => [0o002, {}],
        "tz" => [0o022, { "TZ" => "Pacific/Kiritimati" }], "lang" => [0o022, { "LANG" => "de_DE.UTF-8", "LC_ALL" => "" }]
      }
      trees = runs.to_h do |name, (umask, env)|
        FileUtils.rm_rf(File.join(dir, "releases"))
        run = relspec("compile", "specs/rel.yml", "--out", name, chdir: dir, umask: umask, env: env)
        expect(run.exit_code).to eq(0), run.stderr
        base = File.join(dir, name, "rel")
        files = Dir.glob("**/*", File::FNM_DOTMATCH, base: base).sort.select { |path| File.file?(File.join(base, path)) }
        [name, files.to_h { |path| [path, Digest::SHA256.file(File.join(base, path)).hexdigest] }]
      end
      expect(trees.values.first.keys.grep(/\.debian\.tar\.xz\z/).size).to be >= 2
      trees.each { |name, tree| expect(tree).to eq(trees["umask022"]), "#{name} differs" }

      listing = IO.popen(["tar", "-tvJf", Dir.glob(File.join(dir, "umask077", "rel", "*", "*", "*.debian.tar.xz")).first], &:read)
      expect(listing.lines.grep(/^d/)).to all(start_with("drwxr-xr-x 0/0"))
    end
  end
end
