# frozen_string_literal: true

require "fileutils"
require "open3"
require "rbconfig"
require "securerandom"
require "socket"
require "timeout"
require "tmpdir"

# A real one-node Slurm cluster (Debian's slurm-wlm 22.05: munged,
# slurmctld, slurmd) for the tests, started without systemd inside a
# private network namespace that has only loopback addresses, so nothing
# it does reaches or collides with the machine's network (slurmctld binds
# every interface; 127.0.0.2 is there because glibc's AI_ADDRCONFIG wants a
# loopback address besides 127.0.0.1). Everything lives in one temporary
# folder: config, munge key, state, logs. #stop ends what #start started,
# by pid.
#
#   cluster = SlurmCluster.start(features: %w[amd64])
#   cluster.run("squeue", "--json")     # any command, in the namespace
#   cluster.stop
class SlurmCluster
  NODE = "relspec-node"
  DAEMON_START = 30 # seconds

  attr_reader :dir

  def self.start(**options)
    new(**options).tap(&:start)
  end

  def initialize(features: %w[amd64], cpus: 2)
    @dir = Dir.mktmpdir("relspec-slurm")
    File.chmod(0o755, @dir) # munged refuses a socket in a folder others cannot enter
    @features = features
    @cpus = cpus
    @pids = []
  end

  def conf
    File.join(@dir, "slurm.conf")
  end

  def env
    { "SLURM_CONF" => conf }
  end

  # The command prefix that runs a program in the cluster's namespace.
  def prefix
    ["nsenter", "--net=/proc/#{@namespace}/ns/net", "--"]
  end

  def start
    %w[state spool munge].each { |sub| FileUtils.mkdir_p(File.join(@dir, sub)) }
    File.binwrite(File.join(@dir, "munge", "key"), SecureRandom.bytes(1024))
    File.chmod(0o600, File.join(@dir, "munge", "key"))
    File.write(conf, config)
    # the namespace lives as long as this process (killed in #stop)
    @namespace = spawn("unshare", "--net", "sh", "-c",
                       "ip link set lo up && ip addr add 127.0.0.2/8 dev lo && exec sleep infinity", log: "namespace")
    wait_for("the network namespace") { loopback_up? }
    munge = File.join(@dir, "munge")
    spawn(*prefix, "munged", "-F", "--key-file=#{munge}/key", "--socket=#{munge}/socket", "--pid-file=#{munge}/pid",
          "--log-file=#{munge}/log", "--seed-file=#{munge}/seed", log: "munged")
    wait_for("munged") { File.socket?(File.join(munge, "socket")) }
    spawn(*prefix, "slurmctld", "-D", "-i", log: "slurmctld")
    wait_for("slurmctld") { run("scontrol", "ping").first.include?("is UP") }
    spawn(*prefix, "slurmd", "-D", "-N", NODE, log: "slurmd")
    wait_for("slurmd") { run("sinfo", "--noheader", "--format=%t").first.strip == "idle" }
    self
  rescue StandardError
    stop
    raise
  end

  # Runs a command in the namespace with the cluster's config: [output, status].
  def run(*command)
    Open3.capture2e(env, *prefix, *command)
  end

  # The environment and command line of relspec run in the namespace.
  def relspec_command(*args)
    [env.merge("XDG_CACHE_HOME" => CliRunner::CACHE), *prefix, RbConfig.ruby, CliRunner::EXE, *args]
  end

  # +env+: more environment (the jobs inherit it: sbatch exports it).
  def relspec(*args, chdir:, env: {})
    command = relspec_command(*args)
    stdout, stderr, status = Open3.capture3(command.first.merge(env), *command.drop(1), chdir: chdir, stdin_data: "")
    CliRunner::Run.new(stdout: stdout, stderr: stderr, status: status, max_rss_kib: 0)
  end

  # A folder of commands that run +tools+ in this machine's own network
  # namespace, for PATH: the cluster's namespace has only loopback, while a
  # real node reaches its Debian mirror (sbuild's and mmdebstrap's apt need
  # it). The tools themselves are the real ones.
  def with_network(tools)
    bin = File.join(@dir, "network-bin")
    FileUtils.mkdir_p(bin)
    tools.each do |tool|
      real = File.join("/usr/bin", tool)
      File.write(File.join(bin, tool), "#!/bin/sh\nexec nsenter --net=/proc/#{Process.pid}/ns/net -- #{real} \"$@\"\n")
      File.chmod(0o755, File.join(bin, tool))
    end
    { "PATH" => "#{bin}:#{ENV.fetch('PATH')}" }
  end

  # squeue's jobs (also the finished ones it still shows).
  def jobs
    output, status = run("squeue", "--json")
    raise "squeue failed: #{output}" unless status.success?

    JSON.parse(output).fetch("jobs")
  end

  def stop
    @pids.reverse_each do |pid|
      Process.kill("TERM", pid)
    rescue Errno::ESRCH
      nil
    end
    @pids.reverse_each do |pid|
      Timeout.timeout(10) { Process.wait(pid) }
    rescue Timeout::Error
      Process.kill("KILL", pid)
      Process.wait(pid)
    rescue Errno::ECHILD
      nil
    end
    @pids.clear
    FileUtils.rm_rf(@dir)
  end

  # What the daemons logged, for a failing test's message.
  def logs
    Dir.glob(File.join(@dir, "*.log")).sort.map { |file| "== #{file}\n#{File.read(file)[-3000..] || File.read(file)}" }
       .join("\n")
  end

  private

  def spawn(*command, log:)
    pid = Process.spawn(env, *command, out: File.join(@dir, "#{log}.log"), err: %i[child out], in: File::NULL)
    @pids << pid
    pid
  end

  def loopback_up?
    output, = Open3.capture2e("nsenter", "--net=/proc/#{@namespace}/ns/net", "ip", "-brief", "addr", "show", "lo")
    output.include?("127.0.0.2")
  end

  def wait_for(what)
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + DAEMON_START
    until yield
      raise "#{what} did not start within #{DAEMON_START} s:\n#{logs}" if Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline

      sleep 0.2
    end
  end

  def config
    host = Socket.gethostname
    <<~CONF
      ClusterName=relspec-test
      SlurmctldHost=#{host}(127.0.0.1)
      SlurmUser=root
      SlurmdUser=root
      SlurmctldPort=6817
      SlurmdPort=6818
      AuthType=auth/munge
      AuthInfo=socket=#{@dir}/munge/socket
      CredType=cred/munge
      StateSaveLocation=#{@dir}/state
      SlurmdSpoolDir=#{@dir}/spool
      SlurmctldPidFile=#{@dir}/slurmctld.pid
      SlurmdPidFile=#{@dir}/slurmd.pid
      SlurmctldLogFile=#{@dir}/slurmctld.log
      SlurmdLogFile=#{@dir}/slurmd.log
      # no cgroups and no systemd here: processes tracked by their parent
      ProctrackType=proctrack/linuxproc
      TaskPlugin=task/none
      JobAcctGatherType=jobacct_gather/none
      AccountingStorageType=accounting_storage/none
      SchedulerType=sched/backfill
      SelectType=select/cons_tres
      SelectTypeParameters=CR_Core
      DependencyParameters=kill_invalid_depend
      MinJobAge=600
      ReturnToService=2
      NodeName=#{NODE} NodeAddr=127.0.0.1 NodeHostname=#{host} CPUs=#{@cpus} RealMemory=2000 Features=#{@features.join(',')} State=UNKNOWN
      PartitionName=relspec Nodes=#{NODE} Default=YES MaxTime=INFINITE State=UP
    CONF
  end
end
