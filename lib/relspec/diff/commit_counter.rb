# frozen_string_literal: true

require "open3"

module Relspec
  module Diff
    # Counts the commits between two versions of a package's source when its
    # repository is a local git repository (a path, or $AUTOPROJ_ROOT/… when
    # the workspace is known); otherwise the range is shown without a count.
    class CommitCounter
      def initialize(autoproj_root: nil)
        @autoproj_root = autoproj_root
      end

      def count(url, from, to)
        path = local_path(url)
        return nil unless path && File.directory?(path)

        out, status = Open3.capture2("git", "-C", path, "rev-list", "--count", "#{from}..#{to}", err: File::NULL)
        status.success? ? Integer(out.strip) : nil
      end

      private

      def local_path(url)
        return nil unless url.is_a?(String)
        return url.sub("$AUTOPROJ_ROOT", @autoproj_root) if @autoproj_root && url.start_with?("$AUTOPROJ_ROOT/")

        url.start_with?("/") ? url : nil
      end
    end
  end
end
