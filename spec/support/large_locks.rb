# frozen_string_literal: true

require "fileutils"
require "relspec/plan/lock"
require "relspec/plan/lock_generator"

# Two locks of a generated release of +size+ packages on two targets, as
# LockGenerator writes them: in the old one everything is inherited; in the
# new one +rebuilt+ packages per target are built (a blacklisted root and what
# depends on it), with long cause chains, and a few inherited versions move.
# What the size tests and bench/diff compare (a real plan of 400 packages
# needs 400 packages in a workspace; the diff only reads locks).
module LargeLocks
  TARGETS = %w[bionic/amd64 buster/amd64].freeze
  DIGEST = "0" * 64

  module_function

  # Writes old.yml and new.yml into +dir+; returns their paths.
  def write(dir, size: 400, rebuilt: 50)
    FileUtils.mkdir_p(dir)
    %w[old new].map do |side|
      path = File.join(dir, "#{side}.yml")
      File.write(path, Relspec::Plan::LockGenerator.dump(lock(size, side == "new" ? rebuilt : 0)))
      path
    end
  end

  def lock(size, rebuilt)
    packages = Array.new(size) { |i| format("generated/package_with_a_long_name_%04d", i) }
    targets = TARGETS.to_h do |target|
      codename = target.split("/").first
      [target, packages.each_with_index.to_h { |name, i| [name, entry(name, i, codename, rebuilt)] }]
    end
    Relspec::Plan::Lock.new(release: "big", spec_digest: DIGEST, ancestors: { "base" => { "bionic" => DIGEST, "buster" => DIGEST } },
                            packages: {}, targets: targets, history: Relspec::Plan::History.empty, warnings: [], notes: [])
  end

  def entry(name, index, codename, rebuilt)
    deb = "rock-base-#{name.tr('/_', '--')}"
    minor = rebuilt.positive? && index % 40 == 39 ? 2 : 1 # a few inherited versions move
    unless index < rebuilt
      return Relspec::Plan::Lock::Entry.new(decision: "inherit", deb: deb, version: "1.#{minor}.20200101.000000-1~#{codename}",
                                            from: "base")
    end

    # a chain of up to five steps, ending at the blacklisted package 0
    causes = index.zero? ? [] : (index % 5).downto(0).map { |step| "depends on generated/package_with_a_long_name_#{format('%04d', step)}" }
    causes << 'blacklisted by "generated/package_with_a_long_name_0000" (the project needs its own build of it)'
    # what its debian/ names: the previous package and package 0
    depends = [0, index - 1].uniq.map { |step| "generated/package_with_a_long_name_#{format('%04d', step)}" }
    Relspec::Plan::Lock::Entry.new(decision: "build", deb: deb.sub("rock-base", "rock-big"), version: "1.1.20200101.000000-1~#{codename}",
                                   causes: causes, depends: index.zero? ? [] : depends, debian_digest: DIGEST)
  end
end
