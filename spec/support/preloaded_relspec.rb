# frozen_string_literal: true

require "fileutils"
require "rbconfig"
require "socket"
require "tmpdir"

# Runs relspec in a child forked from a process that has loaded it once
# (preloaded_relspec_server.rb) rather than starting Ruby, Bundler and
# relspec's command line for every run: about 0.5 s of CPU a run, paid
# hundreds of times by the suite. The child is still a process of its own
# that loads and runs exe/relspec: its exit status, standard output and
# error, environment and working folder are the run's, and its peak memory
# is measured as GNU time would.
#
# A run that sets a variable read while Ruby or Bundler start (locale,
# RUBYOPT, GEM_*, BUNDLE_*, TZ) or a umask is started as a process of its
# own by CliRunner, and so is every run when RELSPEC_TEST_SPAWN is set.
class PreloadedRelspec
  SERVER = File.expand_path("preloaded_relspec_server.rb", __dir__)
  START_UP_VARIABLES = /\A(RUBY|GEM_|BUNDLE|LANG\z|LC_|TZ\z)/
  # Ruby, Bundler and relspec's command line load in under a second on an
  # idle machine; CI's load can make it much slower.
  START_DEADLINE = 120

  # What Open3 gives of a Process::Status, for a process that is not this
  # one's child.
  Status = Struct.new(:pid, :exitstatus, :termsig) do
    def exited?
      !exitstatus.nil?
    end

    def success?
      exitstatus&.zero?
    end

    def signaled?
      !termsig.nil?
    end

    def to_s
      exited? ? "pid #{pid} exit #{exitstatus}" : "pid #{pid} SIG#{Signal.signame(termsig)}"
    end
  end

  # One message of the socket's protocol, for both sides: its size, then
  # the Marshal of +value+.
  def self.write_message(connection, value)
    payload = Marshal.dump(value)
    connection.write([payload.bytesize].pack("N"), payload)
  end

  # The next message, or nil when the other side closed the connection.
  def self.read_message(connection)
    size = connection.read(4) or return nil
    Marshal.load(connection.read(size.unpack1("N"))) # rubocop:disable Security/MarshalLoad -- between the test process and its own server
  end

  def self.serves?(env, umask)
    ENV["RELSPEC_TEST_SPAWN"].nil? && umask.nil? && env.keys.none? { |name| name.match?(START_UP_VARIABLES) }
  end

  def initialize(exe)
    @dir = Dir.mktmpdir("relspec-preloaded")
    @socket = File.join(@dir, "socket")
    @log = File.join(@dir, "server.log")
    @owner = Process.pid
    @pid = Process.spawn(RbConfig.ruby, SERVER, exe, @socket, in: File::NULL, out: @log, err: @log)
    wait_for_socket
  end

  # stdout, stderr, Status and peak memory (KiB) of one run.
  def run(args, chdir:, env:)
    connect do |connection|
      readers = [IO.pipe, IO.pipe].map do |reader, writer|
        connection.send_io(writer)
        writer.close
        # read while it runs: a full pipe would stop the child
        Thread.new { reader.read.tap { reader.close } }
      end
      PreloadedRelspec.write_message(connection, [args, chdir, ENV.to_h.merge(env).compact])
      answer = PreloadedRelspec.read_message(connection) or
        raise "the preloaded relspec ended a run without an answer:\n#{File.read(@log)}"
      pid, exitstatus, termsig, rss = answer
      [readers[0].value, readers[1].value, Status.new(pid, exitstatus, termsig), rss]
    end
  end

  # Stops the server; not from a forked copy of the test process.
  def stop
    return unless Process.pid == @owner

    Process.kill("TERM", @pid)
    Process.wait(@pid)
  rescue Errno::ESRCH, Errno::ECHILD
    nil
  ensure
    FileUtils.rm_rf(@dir)
  end

  private

  # UNIXServer.new binds (the file appears) before it listens: a run that
  # connects in between is refused. Seen under CI's load; asked again for
  # a bounded time.
  def connect(&)
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 10
    begin
      UNIXSocket.open(@socket, &)
    rescue Errno::ECONNREFUSED
      raise if Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline

      sleep(0.05)
      retry
    end
  end

  def wait_for_socket
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + START_DEADLINE
    until File.socket?(@socket)
      if Process.wait(@pid, Process::WNOHANG) || Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
        raise "the preloaded relspec did not start:\n#{File.read(@log)}"
      end

      sleep(0.02)
    end
  end
end
