# frozen_string_literal: true

require "digest"
require_relative "demo_workspace"

# Builds demo workspaces and loads them, once per test group where possible
# (a load starts autoproj in a child process: about half a second).
module WorkspaceHelpers
  TARGETS = %w[bionic buster].freeze

  def distributions(codenames = TARGETS)
    Relspec::ReleaseSpec::Distributions::BUILTIN.slice(*codenames)
  end

  def load_catalog(root, codenames = TARGETS)
    require "relspec/catalog/autoproj_source"
    Relspec::Catalog::AutoprojSource.load(root, distributions(codenames))
  end

  # Every file below +dir+ with its content digest and mtime, and every link.
  def tree_state(dir)
    Dir.glob("**/*", File::FNM_DOTMATCH, base: dir).sort.to_h do |entry|
      path = File.join(dir, entry)
      stat = File.lstat(path)
      state = if stat.symlink? then "link:#{File.readlink(path)}"
              elsif stat.directory? then "dir"
              else "#{Digest::SHA256.file(path).hexdigest}:#{stat.mtime.to_f}"
              end
      [entry, state]
    end
  end
end
