# frozen_string_literal: true

require "open3"
require "rbconfig"
require "tmpdir"
require "fileutils"
require_relative "preloaded_relspec"

# Runs the real relspec executable in a child process, as a user would, and
# notes the child's peak memory (GNU time's maximum resident set size) so
# the hostile-input corpus can hold every run to its bound (docs/limits.md).
# Every run of an example is kept (#relspec_runs): the corpus's after hook
# judges them all (spec_helper.rb), so a run that no assertion looks at
# still cannot exit 70 unnoticed.
module CliRunner
  ROOT = File.expand_path("../..", __dir__)
  EXE = File.join(ROOT, "exe", "relspec")
  TIME = "/usr/bin/time" # GNU time (Debian package `time`, installed by bin/setup)
  # The memory bound of the hostile-input corpus: 500 MB.
  HOSTILE_MAX_RSS_KIB = 500 * 1000 * 1000 / 1024
  # A line of a Ruby backtrace ("lib/x.rb:12:in `m'"): what a user sees
  # only with --debug.
  BACKTRACE = /\.rb:\d+:in /
  # A frame of relspec's own code: the executable or lib/relspec.
  OWN_FRAME = %r{(exe/relspec|lib/relspec/\S+\.rb):\d+:in }

  # +max_rss_kib+ is nil for a run started in the background (a killed
  # child writes no memory report); +signalled+: the test sent it a signal.
  Run = Struct.new(:args, :stdout, :stderr, :status, :max_rss_kib, :signalled, keyword_init: true) do
    def exit_code
      status.exitstatus
    end

    # Why this run breaks the promise of docs/limits.md (never exit 70, no
    # backtrace without --debug), or nil. A child that a test killed with a
    # signal did not exit: its stderr is the test's to judge. A signal that
    # came before relspec's first line is answered by Ruby's and Bundler's
    # start-up (a Bundler backtrace without a frame of relspec's): not
    # relspec's promise either.
    def broken_promise
      return unless status.exited?
      return "exit 70" if exit_code == 70
      return if args.to_a.include?("--debug") || !stderr.match?(BACKTRACE)
      return if signalled && !stderr.match?(OWN_FRAME)

      "a Ruby backtrace without --debug"
    end
  end

  # Caches go to a folder of the test run, never to the user's.
  CACHE = Dir.mktmpdir("relspec-test-cache")
  at_exit { FileUtils.rm_rf(CACHE) }
  # The sbuild builds' compiler cache (RELSPEC_CCACHE), of the test run
  # too. Not in CACHE: its folder is closed (0700), and the chroot's build
  # user, a subordinate uid, must reach the cache (relspec makes it its own).
  # Only root's builds have one (Relspec::Builder::Ccache).
  CCACHE = File.join(Dir.mktmpdir("relspec-test-ccache").tap { |dir| File.chmod(0o755, dir) }, "ccache")
  at_exit { FileUtils.rm_rf(File.dirname(CCACHE)) }
  # The sbuild builds' downloaded build-dependencies (RELSPEC_APT_CACHE),
  # of the test run as well, beside the compiler cache for the same reason.
  APT_CACHE = File.join(File.dirname(CCACHE), "apt")
  CCACHE_ENV = Process.uid.zero? ? { "RELSPEC_CCACHE" => CCACHE, "RELSPEC_APT_CACHE" => APT_CACHE } : {}

  # +env+: more environment variables; +umask+: the child's umask;
  # +within+: a command that runs relspec's process as its last arguments
  # (such as FullFilesystem#command). Runs in a child of the preloaded
  # relspec where that is the same as a process of its own (PreloadedRelspec).
  def relspec(*args, chdir: ROOT, env: {}, umask: nil, within: [])
    environment = child_environment(env)
    run = if within.empty? && PreloadedRelspec.serves?(environment, umask)
            stdout, stderr, status, rss = CliRunner.preloaded.run(args, chdir: chdir, env: environment)
            Run.new(args: args, stdout: stdout, stderr: stderr, status: status, max_rss_kib: rss)
          else
            spawned_run(args, chdir, environment, umask, within)
          end
    relspec_runs << run
    run
  end

  # The preloaded relspec of this test process, started on first use.
  def self.preloaded
    PRELOADED_LOCK.synchronize do
      @preloaded ||= PreloadedRelspec.new(EXE).tap { |server| at_exit { server.stop } }
    end
  end
  PRELOADED_LOCK = Mutex.new

  # Starts relspec in the background, for tests that signal it or race it
  # against another run; its stdout is discarded. Returns the pid, which
  # #finish_relspec waits for.
  def spawn_relspec(*args, chdir:, env: {})
    reader, writer = IO.pipe
    pid = Process.spawn(child_environment(env), RbConfig.ruby, EXE, *args, chdir: chdir, in: File::NULL,
                                                                           out: File::NULL, err: writer)
    writer.close
    # read while it runs: a full pipe would stop the child
    spawned_relspecs[pid] = [args, Thread.new { reader.read.tap { reader.close } }]
    pid
  end

  # Sends +signal+ to a run of #spawn_relspec.
  def signal_relspec(pid, signal)
    signalled_relspecs << pid
    Process.kill(signal, pid)
  end

  # Waits for a run of #spawn_relspec to end; its Run.
  def finish_relspec(pid)
    args, stderr = spawned_relspecs.delete(pid)
    _, status = Process.wait2(pid)
    run = Run.new(args: args, stderr: stderr.value, status: status, signalled: !signalled_relspecs.delete(pid).nil?)
    relspec_runs << run
    run
  end

  # The runs of the current example.
  def relspec_runs
    @relspec_runs ||= []
  end

  private

  def spawned_run(args, chdir, environment, umask, within = [])
    options = { chdir: chdir, stdin_data: "" }
    options[:umask] = umask if umask
    Dir.mktmpdir("relspec-run") do |dir|
      report = File.join(dir, "rss")
      # -q: the report holds the number only, whatever the exit status
      stdout, stderr, status = Open3.capture3(environment, *within, TIME, "-q", "-o", report, "-f", "%M", RbConfig.ruby,
                                              EXE, *args, **options)
      Run.new(args: args, stdout: stdout, stderr: stderr, status: status, max_rss_kib: File.read(report).to_i)
    end
  end

  def child_environment(env)
    { "XDG_CACHE_HOME" => CACHE, **CCACHE_ENV }.merge(env)
  end

  def spawned_relspecs
    @spawned_relspecs ||= {}
  end

  def signalled_relspecs
    @signalled_relspecs ||= []
  end
end
