# frozen_string_literal: true

require_relative "release_specs"
require_relative "project"
require_relative "output_tree"
require_relative "target"
require_relative "error"
require_relative "plan/lock_parser"
require_relative "builder/build_plan"
require_relative "builder/build_results"
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
      effective = ReleaseSpec.resolve(path).effective
      release = effective.release
      project = Project.of_spec(path)
      lock = Plan::LockParser.read(project.lock_path(release), release: release)
      raise Error, "#{release} has no #{project.lock_path(release)}: run `relspec compile` first" unless lock

      ancestor = effective.parents.first
      tree = OutputTree.new(out, release)
      inputs = Target.all(effective).map { |target| input(tree, target, release) }
      Reading.new(lock: lock, inputs: inputs, ancestor: ancestor, abi: abi(path, out),
                  ancestor_lock: ancestor && Plan::LockParser.read(project.lock_path(ancestor), release: ancestor)).page
    end

    # target name => AbiSummary of `relspec abi`'s verdicts (Abi.run: the
    # last build's dumps against the nearest ancestor's published ones).
    # A release whose verdicts cannot be computed still gets its page, which
    # says why (its Error's message).
    def abi(path, out)
      require_relative "abi" # abidiff and the ancestors' indexes: only for a release being reported
      Abi.run(path, out: out).targets.to_h { |one| [one.target.to_s, AbiSummary.of(one.entries)] }.compact
    rescue Error => e
      Target.all(ReleaseSpec.resolve(path).effective).to_h { |target| [target.to_s, AbiSummary.failed(e.message)] }
    end

    def input(tree, target, release)
      dir = tree.target_dir(target)
      plan = File.exist?(tree.plan_file(target)) ? Builder::BuildPlan.read(dir) : nil
      results = File.exist?(tree.results_file(target)) ? Builder::BuildResults.load(dir, release: release, target: target) : nil
      # build-results.yml keeps records of packages a narrower plan left
      # out; the page shows (and publishes the logs of) the plan's only
      results = results.within(plan.entries.map(&:source)) if results && plan
      Reading::Input.new(target: target, dir: dir, plan: plan, results: results).freeze
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
