# frozen_string_literal: true

require_relative "error"
require_relative "project"

module Relspec
  # The `relspec osdeps …` use cases (docs/osdeps.md): the files that let
  # autoproj workspaces use a release's binaries. Each takes paths and plain
  # options and returns what it wrote; the CLI only prints it. What each
  # needs is loaded by it: `osdeps select` runs without a plan.
  module Osdeps
    # releases.yml at +path+, +changed+ or not.
    IndexWritten = Struct.new(:path, :changed, keyword_init: true)
    # The package set into +out+: PackageSetWriter::Result and how many
    # files it has.
    PackageSetWritten = Struct.new(:out, :result, :files, keyword_init: true)

    module_function

    # `osdeps render SPEC`: the release's osdeps files into releases/<r>/osdeps/,
    # from the plan (or, +from_repository+, only what the repositories hold).
    # An Osdeps::Files::Written.
    def render(path, timeout:, from_repository:)
      require_relative "plan"
      require_relative "osdeps/files"
      result = Plan.run(path, timeout: timeout)
      effective = result.effective
      dir = Project.new(result.project_root).osdeps_dir(effective.release)
      Files.write_release(result.plan.targets, effective, dir, held_only: from_repository)
    end

    # `osdeps index`: releases.yml for the specs of the folder +specs+,
    # beside it (releases/releases.yml).
    def index(specs:, repo_url: nil, public_key: nil)
      require_relative "osdeps/release_index"
      require_relative "osdeps/files"
      if repo_url && !IndexCheck.http?(repo_url)
        raise InvalidOption, "--repo-url must be an http(s) URL, not #{repo_url.inspect}"
      end

      text = ReleaseIndex.render(indexed_releases(specs), repo_url: repo_url, public_key: public_key)
      path = Project.new(File.dirname(specs)).release_index
      IndexWritten.new(path: path, changed: Files.write_index(path, text))
    end

    # `osdeps package-set`: relspec's autoproj package set for the releases
    # of +specs+ into +out+.
    def package_set(specs:, out:)
      require_relative "osdeps/package_set"
      require_relative "osdeps/package_set_writer"
      files = PackageSet.assemble(indexed_releases(specs))
      PackageSetWritten.new(out: out, result: PackageSetWriter.write(out, files), files: files.size)
    end

    # `osdeps select`: Osdeps::UserSelection (its arguments and result).
    def select(**arguments)
      require_relative "osdeps/user_selection"
      UserSelection.call(**arguments)
    end

    # The release index's view (IndexedRelease) of every spec of +specs+.
    def indexed_releases(specs)
      require_relative "release_specs"
      require_relative "osdeps/indexed_release"
      library = ReleaseSpec::Library.new(specs)
      raise InvalidOption, "#{specs}/ holds no release spec" if library.names.empty?

      library.paths.map { |path| IndexedRelease.from_effective(ReleaseSpec.resolve(path).effective) }
    end
    private_class_method :indexed_releases
  end
end
