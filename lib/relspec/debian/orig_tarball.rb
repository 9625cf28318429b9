# frozen_string_literal: true

require "open3"
require_relative "../error"

module Relspec
  module Debian
    # The upstream tarball of a package (<source>_<upstream>.orig.tar.gz),
    # byte-identical for the same commit on every run and for every
    # distribution, because a repository must never receive two different
    # files under one name.
    #
    # Git checkouts: `git archive` of the commit (files in tree order, mtime =
    # commit time, uid/gid 0, modes 0644/0755, nothing untracked: no VCS or
    # build folders) piped through `gzip -n` (no name, no time stamp). Other
    # sources (unpacked gems, metapackages, checkouts without git): GNU tar
    # with the same normalisation (--sort=name, --mtime, --owner=0 --group=0
    # --numeric-owner, --mode), paths over 256 bytes in GNU long-name
    # records; the prefix is put before member names only, never into the
    # targets of symbolic links (flag S of --transform).
    module OrigTarball
      # Raised when the tarball cannot be made.
      class Failure < Relspec::ToolError; end

      module_function

      # Writes the tarball of +checkout+ at +commit+ (nil: the tree as it is,
      # dated +mtime+, a Time) to +path+, with everything under +prefix+/.
      # +everything+: keep VCS and build folders (an unpacked gem lists its
      # .gitignore or build/ in its metadata, and must be rebuilt from them).
      def write(path, checkout:, commit:, prefix:, mtime:, everything: false)
        command =
          if commit && File.exist?(File.join(checkout, ".git"))
            ["git", "-C", checkout, "-c", "tar.umask=0022", "archive", "--format=tar", "--prefix=#{prefix}/", commit]
          else
            tar_command(checkout, prefix, mtime, everything: everything)
          end
        pipe(command, path)
      end

      def tar_command(dir, prefix, mtime, everything: false)
        excludes = everything ? [] : ["--exclude-vcs", "--exclude=./build", "--exclude=./_build"]
        ["tar", "--sort=name", "--format=gnu", "--mtime=@#{mtime.to_i}", "--owner=0", "--group=0", "--numeric-owner",
         "--mode=u+rwX,go+rX,go-w", *excludes, "--transform=s,^\\.,#{prefix},S", "-C", dir, "-cf", "-", "."]
      end

      # Writes +command+'s output through `gzip -n` to +path+.
      def pipe(command, path)
        File.open(path, "wb") do |out|
          statuses = Open3.pipeline([{ "LC_ALL" => "C.UTF-8", "TZ" => "UTC" }, *command], %w[gzip -n -c],
                                    out: out, err: File::NULL, umask: 0o022)
          raise Failure, "#{command.first} failed making #{File.basename(path)}" unless statuses.all?(&:success?)
        end
      rescue SystemCallError => e
        raise Failure, "cannot write #{path}: #{e.message}"
      end
    end
  end
end
