# frozen_string_literal: true

require "digest"
require_relative "../cache_dir"
require_relative "../cache_writer"
require "find"
require "psych"
require_relative "snapshot_source"
require_relative "git_state"

module Relspec
  class Catalog
    # Catalogs read from workspaces, kept in relspec's XDG cache folder with a
    # fingerprint of everything autoproj read to make them: the workspace's
    # configuration and package sets, and for every package the commit its
    # checkout holds and its manifest. When nothing of that changed, the
    # catalog is taken from the cache instead of loading autoproj again
    # (about a second for 400 packages), which keeps a compile with nothing
    # changed under a second.
    class Cache
      CONFIGURATION = [".autoproj/config.yml", "autoproj", ".autoproj/remotes"].freeze

      def self.default_dir
        CacheDir.for("catalog")
      end

      # +writer+: the CacheWriter the run's caches share (an entry that
      # cannot be written is noted once, and the catalog is used as loaded).
      def initialize(dir = self.class.default_dir, writer: CacheWriter.new)
        @dir = dir
        @writer = writer
      end

      # The catalog of +root+ for +distributions+, from the cache when its
      # fingerprint still holds, else from the block (which loads it), then
      # stored.
      # +manifests+: the pinned manifests the catalog is loaded with (part
      # of the entry's key).
      def fetch(root, distributions, manifests = {})
        return yield unless @dir

        path = entry_path(root, distributions, manifests)
        cached = read(path)
        return cached[:catalog] if cached && cached[:fingerprint] == fingerprint(root, cached[:catalog])

        catalog = yield
        store(path, fingerprint(root, catalog), catalog)
        catalog
      end

      private

      def entry_path(root, distributions, manifests)
        key = [File.expand_path(root), distributions.map { |codename, d| [codename, d.type, d.labels, d.ruby] }.sort,
               manifests.sort].inspect
        File.join(@dir, "#{Digest::SHA256.hexdigest(key)}.yml")
      end

      def read(path)
        return nil unless File.file?(path)

        data = Psych.safe_load(File.read(path))
        return nil unless data.is_a?(Hash) && data["relspec"] == loader_version

        return nil unless SnapshotShape.valid?(data["catalog"])

        { fingerprint: data["fingerprint"], catalog: SnapshotSource.build(data["catalog"]) }
      rescue Psych::Exception
        nil
      end

      def store(path, fingerprint, catalog)
        document = { "relspec" => loader_version, "fingerprint" => fingerprint,
                     "catalog" => { SnapshotSource::FORMAT_KEY => SnapshotSource::FORMAT_VERSION }.merge(catalog.to_h) }
        @writer.write(path, Yaml::Writer.dump(document))
      end

      # Changes to relspec's reading code make old entries useless.
      def loader_version
        @loader_version ||= Digest::SHA256.hexdigest(
          %w[autoproj_loader.rb autoproj_source.rb package.rb package_environment.rb orogen_arguments.rb ruby_extension.rb cmake_defines.rb prefix_markers.rb
             snapshot_source.rb import_patch.rb os_dependencies.rb autoproj_osdeps.rb
             ../catalog.rb].map { |f| File.read(File.join(__dir__, f)) }.join
        )
      end

      def fingerprint(root, catalog)
        digest = Digest::SHA256.new
        configuration_files(root).each { |path| digest << path << "\0" << File.binread(path) << "\0" }
        catalog.packages.each_value do |package|
          checkout = File.join(root, package.source_dir)
          digest << package.name << "\0" << (GitState.commit_of(checkout) || []).join(" ") << "\0"
          %w[manifest.xml package.xml].each do |manifest|
            file = File.join(checkout, manifest)
            digest << manifest << (File.file?(file) ? File.binread(file) : "-") << "\0"
          end
        end
        digest.hexdigest
      end

      # The workspace configuration and every package set autoproj can see
      # (checked-out remote ones and local folders), without their .git.
      def configuration_files(root)
        roots = CONFIGURATION.map { |path| File.join(root, path) } + local_package_sets(root)
        roots.flat_map { |base| files_below(base) }.uniq.sort
      end

      def local_package_sets(root)
        manifest = File.join(root, "autoproj", "manifest")
        data = File.file?(manifest) ? Psych.safe_load(File.read(manifest)) : nil
        entries = data.is_a?(Hash) ? Array(data["package_sets"]) : []
        entries.grep(String).map { |entry| File.expand_path(entry, File.join(root, "autoproj")) }
      rescue Psych::Exception
        []
      end

      def files_below(base)
        return [] unless File.exist?(base)
        return [base] if File.file?(base)

        files = []
        Find.find(base) do |path|
          Find.prune if File.basename(path) == ".git"
          files << path if File.file?(path)
        end
        files
      end
    end
  end
end
