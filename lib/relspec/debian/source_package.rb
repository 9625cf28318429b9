# frozen_string_literal: true

require "fileutils"
require "open3"
require "tmpdir"
require_relative "orig_tarball"
require_relative "debian_dir"
require_relative "overlay"
require_relative "overlay_patch"
require_relative "package_set_patch"
require_relative "emitted"
require_relative "orig_cache"
require_relative "naming"
require_relative "../atomic_file"
require_relative "../temporaries"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Debian
    # Writes one Debian source package (.orig.tar.gz, .debian.tar.xz, .dsc)
    # into its folder of the build tree, with `dpkg-source -b`. The work
    # happens in a temporary folder beside the destination, which replaces the
    # old one only when everything succeeded.
    #
    # The bytes depend only on the inputs: the orig tarball is the upstream
    # tree (overlay files travel as a patch in debian/), and every file and
    # folder relspec puts into debian/ gets a fixed mode whatever the umask.
    class SourcePackage
      STAMP = ".relspec-input"
      # dpkg-source and tar run with this umask and these settings, so that
      # the caller's environment never reaches an archive.
      TOOL_ENV = { "LC_ALL" => "C.UTF-8", "TZ" => "UTC" }.freeze
      TOOL_UMASK = 0o022

      # +input+: BuildInput; +version+: the settled PackageVersion;
      # +digest+: the digest of debian/ it was settled from; +checkout+: the
      # package's source folder; +overlay+: its Overlay; +orig_cache+: folder
      # where orig tarballs are made once per upstream version and shared by
      # every target; +archives+: where an archive import's archive is found
      # (+archives.path_of(package)+: Catalog::ArchiveImport, passed in by
      # compile).
      def initialize(input:, version:, digest:, checkout:, overlay:, orig_cache:, substitutions:, archives:)
        @input = input
        @version = version
        @digest = digest
        @checkout = checkout
        @overlay = overlay
        @orig_cache = orig_cache
        @substitutions = substitutions
        @archives = archives
        @repaired = []
      end

      # Orig cache entries that were damaged and made again by emit: said
      # to the user, since a cache that keeps breaking points at the disk.
      attr_reader :repaired

      def source
        @input.deb_name
      end

      def upstream
        @version.upstream
      end

      def dsc_name
        Naming.dsc(source, @version)
      end

      # What the emitted files are made of; equal stamps mean equal files.
      def stamp
        vcs = @input.package.vcs
        Digest::SHA256.hexdigest([vcs.commit || vcs.sha256, upstream, @version.to_s, @digest].join("\0"))
      end

      # Writes into +dir+ unless it already holds these files. True if written.
      def emit(dir)
        return false if Emitted.new(dir, STAMP).vouches_for?(stamp, dsc_name)

        parent = File.dirname(dir)
        FileUtils.mkdir_p(parent)
        work = Temporaries.path(parent, source)
        Dir.mkdir(work, 0o700)
        begin
          build_in(work)
          Emitted.new(File.join(work, "out"), STAMP).record(stamp)
          File.chmod(0o755, File.join(work, "out"))
          FileUtils.rm_rf(dir)
          File.rename(File.join(work, "out"), dir)
        ensure
          FileUtils.rm_rf(work)
        end
        true
      end

      private

      def build_in(work)
        out = File.join(work, "out")
        FileUtils.mkdir_p(out)
        orig = orig_tarball
        FileUtils.cp(orig, File.join(work, File.basename(orig)))
        tree = File.join(work, "#{source}-#{upstream}")
        run(%W[tar -xzf #{File.basename(orig)}], work)
        write_debian(tree)
        run(["dpkg-source", "--no-check", "-b", File.basename(tree)], work)
        Dir.children(work).select { |name| name.start_with?("#{source}_") }.each do |name|
          File.rename(File.join(work, name), File.join(out, name))
        end
      end

      # The upstream tree, made once per upstream version and copied to
      # every target.
      def orig_tarball
        name = Naming.orig_tarball(source, upstream)
        gem = @input.gem
        # a gem's or an archive's tarball is its own bytes: a different one is another cache entry
        archive = @input.package.vcs.sha256
        key = if gem then gem.sha256[0, 16]
              elsif archive then "archive-#{archive[0, 16]}"
              else "upstream"
              end
        path = File.join(@orig_cache, key, name)
        state = OrigCache.state(path)
        return path if state == :intact

        @repaired << path if state == :damaged
        FileUtils.mkdir_p(File.dirname(path))
        temporary = Temporaries.path(File.dirname(path), name)
        write_orig(temporary)
        OrigCache.store(temporary, path)
        path
      ensure
        File.unlink(temporary) if temporary && File.exist?(temporary)
      end

      def write_orig(path)
        package = @input.package
        prefix = "#{source}-#{upstream}"
        if package.build_type == "meta"
          with_meta_tree { |tree| OrigTarball.write(path, checkout: tree, commit: nil, prefix: prefix, mtime: commit_time) }
        elsif package.build_type == "archive"
          with_archive_tree { |tree| OrigTarball.write(path, checkout: tree, commit: nil, prefix: prefix, mtime: commit_time) }
        elsif @input.gem
          Dir.mktmpdir("relspec-gem") do |tree|
            @input.gem.unpack(tree)
            OrigTarball.write(path, checkout: tree, commit: nil, prefix: prefix, mtime: commit_time, everything: true)
          end
        else
          OrigTarball.write(path, checkout: @checkout, commit: package.vcs.commit, prefix: prefix, mtime: commit_time)
        end
      end

      # An archive import's tree, as autobuild unpacks it: the archive's
      # single top folder, if it has one. tar refuses members that leave
      # the folder (absolute or ../ paths).
      def with_archive_tree
        archive = @archives.path_of(@input.package)
        Dir.mktmpdir("relspec-archive") do |dir|
          run(["tar", "-xf", archive, "-C", dir, "--no-same-owner", "--no-same-permissions"], dir)
          children = Dir.children(dir)
          single = children.size == 1 && File.directory?(File.join(dir, children.first)) &&
                   !File.symlink?(File.join(dir, children.first))
          yield single ? File.join(dir, children.first) : dir
        end
      end

      # A metapackage has no source: its tarball holds a README naming the members.
      def with_meta_tree
        Dir.mktmpdir("relspec-meta") do |dir|
          package = @input.package
          File.write(File.join(dir, "README"), "#{package.description}\n")
          yield dir
        end
      end

      def commit_time
        Time.utc(*@input.package.commit_time.scan(/\d+/).map(&:to_i))
      end

      # An upstream debian/ (utilmm has one, with debian/compat and its own
      # .install files) is not the packaging relspec ships: mixed with the
      # generated one, dh refused the build ("compat level specified both in
      # debian/compat and via build-dependency"). dpkg-source -x removes it
      # as well before unpacking the .debian.tar.xz.
      def write_debian(tree)
        debian = File.join(tree, "debian")
        FileUtils.rm_rf(debian)
        files = DebianDir.render(@input, version: @version)
                         .merge(@overlay.debian_files(@substitutions).transform_values { |content| [content, 0o644] })
        files["rules"] = [files["rules"][0], 0o755]
        patches = patches_over(tree)
        patches.each { |name, content| files["patches/#{name}"] = [content, 0o644] }
        files["patches/series"] = [patches.map { |name, _| "#{name}\n" }.join, 0o644] unless patches.empty?
        files.each do |path, (content, mode)|
          target = File.join(debian, path)
          make_dirs(tree, File.dirname(target))
          File.binwrite(target, content)
          File.chmod(mode, target)
        end
      end

      # The package set's patches first (autoproj applies them at import),
      # then the overlay's files as one patch, then the overlay's patches.
      # The overlay's files are compared with the upstream tree, so an
      # overlay file must not be one a package set patch changes.
      def patches_over(tree)
        package = @input.package
        upstream = lambda do |path|
          file = File.join(tree, path)
          File.file?(file) && !File.symlink?(file) ? File.binread(file) : nil
        end
        imported = package.patches.each_with_index.map do |patch, index|
          PackageSetPatch.of(patch, index: index, package_name: package.name, exists: ->(path) { upstream.call(path) })
        end
        generated = OverlayPatch.of(@overlay.files(@substitutions), upstream: upstream, package_name: package.name,
                                                                    overlay_dir: @overlay.dir)
        imported + (generated ? [[OverlayPatch::NAME, generated]] : []) + @overlay.patches(package.name)
      end

      # mkdir -p with mode 0755 whatever the umask (the folders of debian/
      # go into the .debian.tar.xz with their modes).
      def make_dirs(root, dir)
        missing = []
        until dir == root || File.directory?(dir)
          missing.unshift(dir)
          dir = File.dirname(dir)
        end
        missing.each do |path|
          Dir.mkdir(path)
          File.chmod(0o755, path)
        end
      end

      def run(command, dir)
        output, status = Open3.capture2e(TOOL_ENV, *command, chdir: dir, umask: TOOL_UMASK)
        return if status.success?

        fail_with(command, output)
      rescue SystemCallError => e
        fail_with(command, e.message)
      end

      def fail_with(command, output)
        detail = output.lines.grep(/error|fail|FAILED|can't|cannot/i).first(5).join.strip
        detail = output.lines.last(5).join.strip if detail.empty?
        raise InvalidInput, [Diagnostic.error("source-package", "#{command.first} failed for #{@input.package.name} " \
                                                                "(#{source}): #{detail}",
                                              location: Location.file_only(source),
                                              hint: "check the package's overlays (overlays/#{@input.package.name}/)")]
      end
    end
  end
end
