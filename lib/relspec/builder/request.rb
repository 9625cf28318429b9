# frozen_string_literal: true

require_relative "../target"

module Relspec
  module Builder
    # What a backend gets to build one source package (docs/ARCHITECTURE.md,
    # "Build backends"):
    # +source+/+version+: the Debian source package; +dsc+: its .dsc;
    # +target+: a Target (codename, arch); +repositories+: the apt
    # repositories the build may take build-dependencies from (Repository);
    # +local_debs+: .debs built earlier in this run that it may need;
    # +output_dir+: where the produced files go; +log+: the log file.
    Request = Struct.new(:source, :version, :dsc, :target, :repositories, :local_debs, :output_dir, :log,
                         keyword_init: true)

    Target = Relspec::Target

    # An apt repository a build can use: +uri+ (http(s) or a local folder),
    # the +suite+ (the target's codename) and +components+; +keyring+: the
    # key file its Release is signed with; +trusted+: used unsigned because
    # the spec says `trusted: true`.
    Repository = Struct.new(:name, :uri, :suite, :components, :keyring, :trusted, keyword_init: true) do
      def local?
        !uri.match?(%r{\A[a-z]+://})
      end

      # The .debs a local repository holds for +target+ (its pool; which of
      # them a build takes is left to the version relations).
      def pool_debs(target)
        return [] unless local? && File.directory?(File.join(uri, "dists", target.codename))

        Dir.glob(File.join(uri, "pool", "**", "*_{#{target.arch},all}.deb")).sort
           .select { |deb| deb.include?("~#{target.codename}") }
      end
    end
  end
end
