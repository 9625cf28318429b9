# frozen_string_literal: true

require "fileutils"
require "open3"
require_relative "release_specs"
require_relative "target"
require_relative "atomic_file"
require_relative "apt/cache"
require_relative "builder/chroot"
require_relative "mirror/binary_index"
require_relative "mirror/closure"
require_relative "mirror/sources"
require_relative "mirror/apt_repository"
require_relative "mirror/download"
require_relative "mirror/proof"
require_relative "mirror/report"
require_relative "mirror/manifest"
require_relative "mirror/integrity"

module Relspec
  # `relspec mirror SPEC --out DIR`: a field mirror of a release. Everything
  # a machine needs to install the release with no network: the release's
  # packages, its ancestors' that it inherits, their whole runtime closure
  # from the distribution and the distribution's minimal system, as one
  # reprepro repository, with the proof that it is complete (static and
  # dynamic, Mirror::Proof) written beside it. Running it again updates the
  # mirror: adds what is new, drops what nothing needs any more.
  # `relspec mirror verify DIR` checks a mirror again, offline.
  module Mirror
    VERIFIED = "VERIFIED.md"
    INCOMING = ".relspec-incoming"

    # +targets+: "codename/arch" strings (empty: every target of the spec);
    # +progress+: an IO for one line per step, or nil; +notes+: an IO for
    # what the run repaired on its way (a stale reprepro lock), or nil.
    def self.run(path, out:, targets: [], timeout: 10, progress: nil, install: true, notes: nil)
      resolution = ReleaseSpec.resolve(path)
      effective = resolution.effective
      all = Target.all(effective)
      selected = Target.select(targets.empty? ? nil : targets, all, effective.release)
      sign_with = effective.repository&.sign_with
      repository = AptRepository.new(out, targets: selected, sign_with: sign_with)
      stale = repository.configure(left_out: all - selected)
      notes&.puts(Publish::StaleRepreproLock.note(stale)) if stale
      sources = Sources.new(resolution, timeout: timeout, cache: Apt::Cache.new(Apt::Cache.default_dir))
      key = sign_with && export_key(sign_with, repository.dir, effective.release)
      made = selected.map { |target| fill(repository, sources.read(target), target, progress) }
      repository.export
      manifest = Manifest.new(release: effective.release, key: key && File.basename(key),
                              targets: made.to_h { |target, seeds, _| [target, seeds] })
      reports = made.map do |target, seeds, report|
        prove(repository, target, seeds, key, install: install).then do |checks|
          Report::TargetReport.new(**report.to_h, checks: checks)
        end
      end
      write(repository, manifest, key, Report.new(effective.release, reports))
    end

    # Checks the mirror in +dir+ again from its own files: its indices
    # against their Release files and its pool against its indices, both
    # ways (Integrity; every file the indices list is there with the listed
    # size and SHA256), and both proofs pass.
    def self.verify(dir, install: true)
      manifest = Manifest.read(dir)
      repository = AptRepository.new(dir, targets: manifest.targets.keys)
      key = manifest.key && File.join(repository.dir, manifest.key)
      files = Integrity.new(repository, manifest.targets.keys, key: key).check
      reports = manifest.targets.map do |target, seeds|
        index = repository.index(target)
        counts = { "total" => index.names.size, "release" => seeds.size,
                   "required" => index.binaries.count(&:required?), "bytes" => index.binaries.sum(&:size) }
        Report::TargetReport.new(target: target, counts: counts, changes: nil, missing: missing_files(repository, index),
                                 checks: prove(repository, target, seeds, key, install: install))
      end
      Report.new(manifest.release, reports, files: files)
    end

    def self.fill(repository, read, target, progress)
      closure = Closure.of(read.index, read.seeds)
      closure.add(read.required, "the minimal #{target.codename} system")
      wanted = closure.binaries.values
      current = repository.index(target)
      add = wanted.reject { |binary| (held = current[binary.name]) && held.sha256 == binary.sha256 }
                  .sort_by(&:name)
      remove = (current.names - closure.names).sort
      download = Download.new(File.join(repository.dir, INCOMING))
      files = download.fetch(add, progress: progress && lambda { |done, total, binary|
        progress.puts("relspec: #{target}: [#{done}/#{total}] #{binary}")
      })
      repository.include(target, files)
      repository.remove(target, remove)
      download.clean
      counts = counts(closure, read)
      changes = { "added" => add.size, "added_bytes" => add.sum(&:size), "removed" => remove.size,
                  "kept" => wanted.size - add.size }
      missing = closure.missing.map(&:to_s).sort
      [target, read.seeds.select { |name| closure.binaries.key?(name) }.sort,
       Report::TargetReport.new(target: target, counts: counts, changes: changes, missing: missing, checks: [],
                                pinned: pinned(read.index, closure))]
    end

    # The release's packages the mirror holds although the distribution
    # has a higher version of their name (BinaryIndex#pinned).
    def self.pinned(index, closure)
      index.pinned.select { |pin| closure.binaries.key?(pin.kept.name) }.map do |pin|
        "#{pin.kept} of #{pin.kept.origin.label} is kept; the distribution's #{pin.shadowed.version} " \
          "(#{pin.shadowed.origin.label}) is not mirrored"
      end
    end

    def self.counts(closure, read)
      binaries = closure.binaries.values
      { "total" => binaries.size, "release" => read.seeds.count { |name| closure.binaries.key?(name) },
        "inherited" => binaries.count { |binary| read.ancestors.include?(binary.origin.label) },
        "distribution" => binaries.count { |binary| binary.origin.distribution },
        "required" => read.required.size, "bytes" => binaries.sum(&:size) }
    end

    def self.prove(repository, target, seeds, key, install:)
      proof = Proof.new(repository)
      checks = [proof.static(target)]
      checks << if install
                  proof.dynamic(target, seeds, sign_key: key, arch_runs: runs?(target.arch))
                else
                  Proof::Check.new(name: "dynamic", status: "skipped", problems: [],
                                   detail: "--no-install: not installed").freeze
                end
      checks
    end

    # This machine's own architecture, or one it runs by emulation: the
    # builder's own check (Builder::Emulation).
    def self.runs?(arch)
      Builder::Emulation.new(Builder::Chroot.host_arch).check(arch)
      true
    rescue BuildError
      false
    end

    # Files the mirror's indices list that are absent or not what the
    # index says, each with the packages of the mirror that need it.
    def self.missing_files(repository, index)
      index.binaries.sort_by(&:name).filter_map do |binary|
        path = repository.pool_file(binary)
        next if File.file?(path) && File.size(path) == binary.size && Digest::SHA256.file(path).hexdigest == binary.sha256

        needers = index.binaries.select do |other|
          other.depends.any? { |group| group.any? { |relation| relation.name == binary.name } }
        end.map(&:name).sort
        "#{binary.filename} (#{binary}) is #{File.exist?(path) ? 'damaged' : 'missing'}" \
          "#{" (needed by #{needers.join(', ')})" unless needers.empty?}"
      end
    end

    def self.export_key(key_id, dir, release)
      armored, status = Open3.capture2("gpg", "--batch", "--armor", "--export", key_id)
      raise ToolError, "gpg cannot export the key #{key_id} (repository.sign_with)" unless status.success? && !armored.empty?

      name = "#{release}-mirror.asc"
      AtomicFile.write(File.join(dir, name), armored)
      File.join(dir, name)
    end

    def self.write(repository, manifest, key, report)
      dir = repository.dir
      release = manifest.release
      manifest.write(dir)
      AtomicFile.write(File.join(dir, VERIFIED), report.markdown)
      codenames = manifest.targets.keys.map(&:codename).uniq.sort
      options = key ? "signed-by=/etc/apt/keyrings/#{File.basename(key)}" : "trusted=yes"
      AtomicFile.write(File.join(dir, "#{release}-mirror.list"),
                       codenames.map { |codename| "deb [#{options}] file://#{dir} #{codename} main\n" }.join)
      AtomicFile.write(File.join(dir, "#{release}-mirror.sources"),
                       "Types: deb\nURIs: file://#{dir}\nSuites: #{codenames.join(' ')}\nComponents: main\n" \
                       "#{key ? "Signed-By: /etc/apt/keyrings/#{File.basename(key)}" : 'Trusted: yes'}\n")
      report
    end
  end
end
