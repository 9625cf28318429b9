# frozen_string_literal: true

require_relative "release_specs"
require_relative "project"
require_relative "output_tree"
require_relative "target"
require_relative "error"
require_relative "plan/lock_parser"
require_relative "target_build"
require_relative "report/reading"
require_relative "report/html_renderer"
require_relative "report/json_renderer"
require_relative "report/abi_summary"
require_relative "report/folder"

module Relspec
  # `relspec report` (and `relspec publish`, next to the repository): a
  # release at a glance, one static page (docs/report.md) made from the
  # lock, each target's plan.yml, build-results.yml and logs. The same inputs
  # give the same bytes.
  module Report
    FORMATS = %w[html json].freeze
    FILES = { "html" => "index.html", "json" => "report.json" }.freeze

    module_function

    # Reads the release of the spec at +path+ (+out+: where compile and
    # build wrote) and writes its report in +format+ into +dir+ (default
    # <out>/<release>/report/). Returns the written file's path.
    def run(path, out:, format: "html", dir: nil)
      raise InvalidOption, "unknown format #{format.inspect} (known: #{FORMATS.join(', ')})" unless FORMATS.include?(format)

      page, logs = read(path, out: out)
      write(page, logs, dir || OutputTree.new(out, page.release).report_dir, format)
    end

    # The Page of the release of the spec at +path+, and the logs it links
    # to (link => file).
    def read(path, out:)
      resolution = ReleaseSpec.resolve(path)
      release = resolution.effective.release
      project = Project.of_spec(path)
      lock = Plan::LockParser.read(project.lock_path(release), release: release)
      raise Error, "#{release} has no #{project.lock_path(release)}: run `relspec compile` first" unless lock

      tree = OutputTree.new(out, release)
      of(resolution, project, lock, Target.all(resolution.effective).map { |target| TargetBuild.read(tree, target) })
    end

    # The Page of a release already read (publish hands its own reading on):
    # +resolution+ and +project+ of its spec, its +lock+ (Plan::Lock) and
    # +builds+, the TargetBuild of each target.
    def of(resolution, project, lock, builds)
      ancestor = resolution.effective.parents.first
      Reading.new(lock: lock, inputs: builds, ancestor: ancestor, abi: abi(resolution, builds),
                  ancestor_lock: ancestor && Plan::LockParser.read(project.lock_path(ancestor), release: ancestor)).page
    end

    # target name => AbiSummary of `relspec abi`'s verdicts (Abi.of: the
    # last build's dumps against the nearest ancestor's published ones).
    # A release whose verdicts cannot be computed still gets its page, which
    # says why (its Error's message).
    def abi(resolution, builds)
      require_relative "abi" # abidiff and the ancestors' indexes: only for a release being reported
      Abi.of(resolution, builds).targets.to_h { |one| [one.target.to_s, AbiSummary.of(one.entries)] }.compact
    rescue Error => e
      builds.to_h { |build| [build.target.to_s, AbiSummary.failed(e.message)] }
    end

    # Writes +page+ as FILES[format] into +dir+ with a copy of each log it
    # links to (logs no longer linked are removed; Folder). Returns the
    # file's path.
    def write(page, logs, dir, format)
      text = format == "json" ? JsonRenderer.render(page) : HtmlRenderer.new.render(page)
      Folder.new(dir).write(text, logs, FILES.fetch(format))
    end

    # Raises naming a link in +dir+ that #write of +logs+ in +format+
    # would go through: publish asks before it touches the repository.
    def check(logs, dir, format)
      Folder.new(dir).check(logs, FILES.fetch(format))
    end
  end
end
