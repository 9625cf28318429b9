# frozen_string_literal: true

require "open3"
require_relative "git_repository"

module Relspec
  class Catalog
    # The commit each checkout holds and its UTC commit time. Read from the
    # .git folders directly (GitRepository); checkouts it cannot read are asked
    # with one `git log` each.
    module GitState
      module_function

      # +checkouts+: package name => source dir relative to +root+.
      # Returns name => [commit, "YYYY-MM-DDTHH:MM:SSZ"] for git checkouts.
      # (Reading .git files takes well under a millisecond per checkout:
      # threads did not make it faster.)
      def read(root, checkouts)
        checkouts.filter_map do |name, dir|
          state = commit_of(File.join(root, dir))
          state && [name, state]
        end.to_h
      end

      def commit_of(dir)
        return nil unless File.exist?(File.join(dir, ".git"))

        commit, seconds = GitRepository.new(dir).head
        return [commit, utc(seconds)] if commit

        log(dir, "HEAD")
      end

      def utc(seconds)
        Time.at(seconds).utc.strftime("%Y-%m-%dT%H:%M:%SZ")
      end

      # Where a pin points in a checkout: [commit, time] or nil if the
      # checkout does not have it (autoproj clones name their remote
      # "autobuild", so branches are looked up there first).
      def resolve(dir, ref, value)
        return nil unless File.exist?(File.join(dir, ".git"))

        candidates =
          case ref
          when "commit" then [value]
          when "tag" then ["refs/tags/#{value}"]
          when "branch" then ["refs/remotes/autobuild/#{value}", "refs/heads/#{value}"]
          end
        candidates.each do |candidate|
          output, status = Open3.capture2("git", "-C", dir, "rev-parse", "--verify", "--quiet", "--end-of-options",
                                          "#{candidate}^{commit}", err: File::NULL)
          return log(dir, output.strip) if status.success?
        end
        nil
      end

      def log(dir, revision)
        output, status = Open3.capture2("git", "-C", dir, "log", "-1", "--format=%H %ct", revision, "--", err: File::NULL)
        return nil unless status.success?

        commit, seconds = output.split
        [commit, utc(Integer(seconds))]
      end
    end
  end
end
