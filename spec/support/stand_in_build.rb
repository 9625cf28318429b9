# frozen_string_literal: true

require "digest"
require "fileutils"
require "yaml"
require_relative "host_build"

# Stands in for `relspec build` (developed on another branch) until the lead
# merges it: builds what `relspec compile` wrote for one target, in plan.yml's
# order, with dpkg-buildpackage through HostBuild (each build sees the .debs
# built before it at /opt, in a private mount namespace), and writes
# build-results.yml in the agreed format. Once the real command is merged,
# tests should call `relspec build --backend host` instead.
class StandInBuild
  attr_reader :target_dir, :host

  # +out+: compile's --out; +target+: "codename/arch"; +installed+: .debs
  # of ancestor releases the builds need at /opt.
  def initialize(out, release, target, scratch, installed: [])
    @release = release
    @target = target
    @target_dir = File.join(out, release, target.tr("/", "-"))
    @host = HostBuild.new(scratch)
    installed.each { |deb| @host.install(deb) }
  end

  # Builds every package of plan.yml; +failed+: sources recorded as failed
  # (and their reverse dependencies as skipped) without building them.
  def run(failed: [])
    plan = YAML.safe_load_file(File.join(@target_dir, "plan.yml"))
    down = []
    packages = plan.fetch("builds").to_h do |build|
      source = build.fetch("source")
      entry = { "package" => build.fetch("package"), "version" => build.fetch("version"), "duration" => 1.0,
                "log" => "logs/#{source}.log" }
      if failed.include?(source)
        down << source
        [source, entry.merge("status" => "failed", "reason" => "failed on purpose (test)")]
      elsif (blocker = build.fetch("build_depends").find { |dep| down.include?(dep) })
        down << source
        [source, entry.merge("status" => "skipped", "reason" => "needs #{blocker}, which failed")]
      else
        [source, entry.merge("status" => "built", "files" => build_one(source, build.fetch("dsc")))]
      end
    end
    write(packages.sort.to_h)
  end

  def write(packages)
    File.write(File.join(@target_dir, "build-results.yml"),
               YAML.dump("relspec_build_results" => 1, "release" => @release, "target" => @target, "backend" => "host",
                         "packages" => packages))
  end

  private

  def build_one(source, dsc)
    debs = @host.build_and_install(File.join(@target_dir, dsc))
    results = File.join(@target_dir, "results", source)
    FileUtils.mkdir_p(results)
    produced = debs + Dir.glob(File.join(File.dirname(debs.first), "#{source}_*.{buildinfo,changes}"))
    produced.sort.map do |file|
      FileUtils.cp(file, results)
      name = File.join("results", source, File.basename(file))
      path = File.join(@target_dir, name)
      { "name" => name, "sha256" => Digest::SHA256.file(path).hexdigest, "size" => File.size(path) }
    end
  end
end
