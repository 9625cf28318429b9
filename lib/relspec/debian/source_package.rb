# frozen_string_literal: true

require "fileutils"
require "open3"
require "tmpdir"
require_relative "orig_tarball"
require_relative "debian_dir"
require_relative "overlay"
require_relative "../atomic_file"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Debian
    # Writes one Debian source package (.orig.tar.gz, .debian.tar.xz, .dsc)
    # into its folder of the build tree, with `dpkg-source -b`. The work
    # happens in a temporary folder beside the destination, which replaces the
    # old one only when everything succeeded.
    class SourcePackage
      STAMP = ".relspec-input"

      # +input+: DebianDir input; +files+: a block rendering debian/ (called
      # only when the package is emitted); +digest+: the digest of debian/
      # recorded in the lock; +version+: the full version; +checkout+: the
      # package's source folder;
      # +overlay+: its Overlay; +orig_cache+: folder where orig tarballs are
      # made once per upstream version and shared by every target.
      def initialize(input:, files:, digest:, version:, checkout:, overlay:, orig_cache:, substitutions:)
        @input = input
        @render = files
        @digest = digest
        @version = version
        @checkout = checkout
        @overlay = overlay
        @orig_cache = orig_cache
        @substitutions = substitutions
      end

      def source
        @input.fetch(:deb_name)
      end

      def upstream
        @input.fetch(:upstream)
      end

      def dsc_name
        "#{source}_#{@version.sub(/\A\d+:/, '')}.dsc"
      end

      # What the emitted files are made of; equal stamps mean equal files.
      def stamp
        Digest::SHA256.hexdigest([@input.fetch(:package).vcs.commit, upstream, @version, @digest].join("\0"))
      end

      # Writes into +dir+ unless it already holds these files. True if written.
      def emit(dir)
        return false if File.file?(File.join(dir, STAMP)) && File.read(File.join(dir, STAMP)) == stamp &&
                        File.file?(File.join(dir, dsc_name))

        parent = File.dirname(dir)
        FileUtils.mkdir_p(parent)
        work = Dir.mktmpdir(".#{source}-", parent)
        begin
          build_in(work)
          File.write(File.join(work, "out", STAMP), stamp)
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

      # Made once per upstream version (and overlay) and copied to every target.
      def orig_tarball
        name = OrigTarball.file_name(source, upstream)
        overlay_files = @overlay.files(@substitutions)
        # what the tarball is made of besides the commit: a gem's own bytes, an overlay
        made_of = [@input[:gem]&.sha256, *overlay_files.sort.flatten].compact
        key = made_of.empty? ? "plain" : Digest::SHA256.hexdigest(made_of.join("\0"))[0, 16]
        path = File.join(@orig_cache, key, name)
        return path if File.file?(path)

        FileUtils.mkdir_p(File.dirname(path))
        temporary = "#{path}.#{Process.pid}.#{Thread.current.object_id}.tmp"
        package = @input.fetch(:package)
        if package.build_type == "meta"
          with_meta_tree { |tree| OrigTarball.write(temporary, checkout: tree, commit: nil, prefix: "#{source}-#{upstream}", mtime: commit_time) }
        elsif overlay_files.empty? && package.build_type != "gem"
          OrigTarball.write(temporary, checkout: @checkout, commit: package.vcs.commit, prefix: "#{source}-#{upstream}",
                                       mtime: commit_time)
        else
          with_overlaid_tree(overlay_files) do |tree|
            OrigTarball.write(temporary, checkout: tree, commit: nil, prefix: "#{source}-#{upstream}", mtime: commit_time,
                                         everything: !@input[:gem].nil?)
          end
        end
        File.rename(temporary, path)
        path
      ensure
        File.unlink(temporary) if temporary && File.exist?(temporary)
      end

      # A metapackage has no source: its tarball holds a README naming the members.
      def with_meta_tree
        Dir.mktmpdir("relspec-meta") do |dir|
          package = @input.fetch(:package)
          File.write(File.join(dir, "README"), "#{package.description}\n")
          yield dir
        end
      end

      # The upstream tree (the commit's files, or the unpacked gem) with the
      # overlay's files over it.
      def with_overlaid_tree(overlay_files)
        Dir.mktmpdir("relspec-overlay") do |dir|
          tree = File.join(dir, "tree")
          FileUtils.mkdir_p(tree)
          unpack_upstream(dir, tree)
          overlay_files.each do |path, content|
            target = File.join(tree, path)
            FileUtils.mkdir_p(File.dirname(target))
            File.binwrite(target, content)
          end
          yield tree
        end
      end

      def unpack_upstream(dir, tree)
        gem = @input[:gem]
        return gem.unpack(tree) if gem

        archive = File.join(dir, "source.tar.gz")
        OrigTarball.pipe(["git", "-C", @checkout, "archive", "--format=tar", @input.fetch(:package).vcs.commit], archive)
        run(%W[tar -xzf #{archive} -C #{tree}], dir)
      end

      def commit_time
        Time.utc(*@input.fetch(:package).commit_time.scan(/\d+/).map(&:to_i))
      end

      def write_debian(tree)
        debian = File.join(tree, "debian")
        files = @render.call.merge(@overlay.debian_files(@substitutions).transform_values { |content| [content, 0o644] })
        files["rules"] = [files["rules"][0], 0o755]
        patches = @overlay.patches(@input.fetch(:package).name)
        patches.each { |name, content| files["patches/#{name}"] = [content, 0o644] }
        files["patches/series"] = [patches.map { |name, _| "#{name}\n" }.join, 0o644] unless patches.empty?
        files.each do |path, (content, mode)|
          target = File.join(debian, path)
          FileUtils.mkdir_p(File.dirname(target))
          File.binwrite(target, content)
          File.chmod(mode, target)
        end
      end

      def run(command, dir)
        output, status = Open3.capture2e({ "LC_ALL" => "C.UTF-8" }, *command, chdir: dir)
        return if status.success?

        fail_with(command, output)
      rescue SystemCallError => e
        fail_with(command, e.message)
      end

      def fail_with(command, output)
        detail = output.lines.grep(/error|fail|FAILED|can't|cannot/i).first(5).join.strip
        detail = output.lines.last(5).join.strip if detail.empty?
        raise InvalidInput, [Diagnostic.error("source-package", "#{command.first} failed for #{@input.fetch(:package).name} " \
                                                                "(#{source}): #{detail}",
                                              location: Location.file_only(source),
                                              hint: "check the package's overlays (overlays/#{@input.fetch(:package).name}/)")]
      end
    end
  end
end
