# frozen_string_literal: true

# bench/sbuild: the per-package overhead of the sbuild backend (clean
# unshare chroot) over the host backend, on the same small package, in one
# run; and that a second sbuild run makes no chroot. The chroot tarball
# lives in relspec's cache (XDG_CACHE_HOME): made by the first sbuild build
# when missing, and timed separately then.
#
#   bundle exec ruby bench/sbuild.rb
require "open3"
require "rbconfig"
require "tmpdir"
require "yaml"
require_relative "timing"
require_relative "../spec/support/build_release"

def relspec(dir, *args)
  Timing.seconds do
    output, status = Open3.capture2e(RbConfig.ruby, BuildRelease::EXE, *args, chdir: dir)
    raise "relspec #{args.first} failed:\n#{output}" unless status.success?
  end
end

def duration(release)
  records = YAML.safe_load(File.read(File.join(release.target_dir, "build-results.yml"))).fetch("packages")
  records.values.first.fetch("duration")
end

Dir.mktmpdir("relspec-bench-sbuild") do |dir|
  release = BuildRelease.new(dir, "sbench")
  release.package("base/small")
  release.compile
  build = %w[build specs/sbench.yml --out out --quiet --rebuild --backend]
  prepare = relspec(dir, "build", "specs/sbench.yml", "--out", "out", "--quiet", "--prepare")
  relspec(dir, *build, "host")
  host = duration(release)
  relspec(dir, *build, "sbuild")
  sbuild = duration(release)
  again = relspec(dir, "build", "specs/sbench.yml", "--out", "out", "--quiet", "--prepare")

  puts format("first --prepare             %6.1f s (makes the chroot unless the cache has it)", prepare)
  puts format("host backend, one package   %6.1f s", host)
  puts format("sbuild, same package        %6.1f s  (overhead %.1f s per package, ratio %.1f)", sbuild,
              sbuild - host, sbuild / host)
  puts format("second --prepare            %6.2f s (no chroot made)", again)
end
