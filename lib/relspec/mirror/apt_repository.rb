# frozen_string_literal: true

require_relative "../error"
require_relative "../reprepro/config"
require_relative "../reprepro/runner"
require_relative "binary_index"
require_relative "folder"
require_relative "../publish/stale_reprepro_lock"
require_relative "../display_path"
require_relative "../printable"
require_relative "../target"

module Relspec
  module Mirror
    # The mirror's own apt repository, made and changed with reprepro: one
    # distribution per codename with the mirrored architectures; packages
    # go in and out by name, the pool only through reprepro. The mirror's
    # folder holds nothing else of relspec's but its marker (Folder),
    # mirror.yml, VERIFIED.md, the sources snippets and the public key.
    class AptRepository
      attr_reader :dir

      # +targets+: every Target the mirror holds; +sign_with+: a gpg key id.
      def initialize(dir, targets:, sign_with: nil)
        @dir = File.expand_path(dir)
        @targets = targets
        @config = Reprepro::Config.new(label: "relspec mirror", targets: targets, source: false, sign_with: sign_with,
                                       description: "field mirror of a release and what it needs from %<codename>s")
        @reprepro = Reprepro::Runner.new(@dir)
      end

      # Takes the folder (Folder: one relspec made, never someone else's),
      # writes conf/, and removes reprepro's lock (db/lockfile) when no live
      # reprepro uses the mirror (a run killed while reprepro worked left it,
      # and every later reprepro would wait for it, then fail): publish's own
      # rule, Publish::StaleRepreproLock. The removed lock's path, or nil.
      # +left_out+: the spec's targets this run does not make (--target); one
      # the mirror holds is refused before conf/ is written: conf/ without it
      # would have reprepro drop its packages (or refuse its folders).
      def configure(left_out: [])
        Folder.claim(@dir)
        refuse_dropping(held_targets & left_out)
        @config.write(File.join(@dir, "conf"))
        begin
          Publish::StaleRepreproLock.clear(@dir)
        rescue SystemCallError => e # a db/lockfile that is a folder, a read-only db/
          raise ToolError, "cannot remove reprepro's stale lock in #{@dir}/db: #{e.message.sub(/ @ .*/, '')}"
        end
      end

      def index_path(target)
        File.join(@dir, "dists", target.codename, "main", "binary-#{target.arch}", "Packages")
      end

      # What the mirror holds for +target+ now (an empty index before the
      # first run): a BinaryIndex whose origin is the mirror itself.
      def index(target)
        path = index_path(target)
        index = BinaryIndex.new
        return index unless File.file?(path)

        index.add(File.read(path), origin: Origin.new(label: "mirror", fetcher: nil, distribution: false), where: path)
      end

      # reprepro includedeb of +files+ into +target+'s distribution.
      def include(target, files)
        files.each_slice(200) { |slice| @reprepro.includedeb(target.codename, slice, arch: target.arch) }
      end

      def remove(target, names)
        names.each_slice(200) { |slice| @reprepro.remove(target.codename, slice, arch: target.arch) }
      end

      def export
        @reprepro.export
        @reprepro.clearvanished if File.directory?(File.join(@dir, "db"))
      end

      # The pool file of +binary+ as the mirror's index names it.
      def pool_file(binary)
        File.join(@dir, binary.filename)
      end

      # The targets the mirror's conf/distributions (relspec's own, from the
      # previous run) configures; none for a new mirror.
      def held_targets
        conf = File.join(@dir, "conf", "distributions")
        return [] unless File.file?(conf)

        File.read(conf).split(/\n\s*\n/).flat_map do |block|
          codename = block[/^Codename: (\S+)$/, 1]
          archs = block[/^Architectures: (.*)$/, 1].to_s.split
          codename ? archs.map { |arch| Target.new(codename, arch).freeze } : []
        end
      end

      private

      def refuse_dropping(dropped)
        return if dropped.empty?

        made = @targets.join(", ")
        raise InvalidOption, "the mirror in #{Printable.text(DisplayPath.of(@dir))} holds #{dropped.map(&:to_s).sort.join(', ')} " \
                             "too: a run for #{made} alone would remove it from the mirror; give a --target for every " \
                             "target it holds (#{(held_targets | @targets).map(&:to_s).sort.join(', ')}), or make the " \
                             "mirror of #{made} in another --out"
      end
    end
  end
end
