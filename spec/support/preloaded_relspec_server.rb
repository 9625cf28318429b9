# frozen_string_literal: true

# The server side of PreloadedRelspec (spec/support/preloaded_relspec.rb):
#
#   ruby preloaded_relspec_server.rb EXE SOCKET
#
# Loads relspec's code, then answers each connection on the UNIX socket
# SOCKET in a process of its own, which forks the run's relspec: that child
# takes the request's standard output and error, environment, working
# folder and arguments and then loads EXE itself, so everything after
# Ruby's and Bundler's start-up is the executable's own code. The
# connection's process waits for the child and answers with its pid, exit
# status or signal, and its peak memory.
require "io/wait"
require "socket"
require_relative "preloaded_relspec"

exe, socket_path = ARGV
root = File.expand_path("..", File.dirname(exe))
# Every file of lib/relspec and the gems they load (autoproj, dry-schema:
# ~1.3 s together), which a run of its own loads when its command needs
# them. The package set's files are autoproj's to load, not relspec's.
Dir.glob(File.join(root, "lib", "relspec", "**", "*.rb")).sort.each do |file|
  require file unless file.include?("/osdeps/package_set/")
end
# and the constants those gems load on first use (dry-schema's and
# dry-types' through Zeitwerk: ~0.2 s of a first validation)
Zeitwerk::Loader.eager_load_all if defined?(Zeitwerk::Loader)

# The child that is the relspec run. Its peak memory (VmHWM) is what GNU
# time reports for a process of its own; written from the last at_exit
# handler, after relspec's own have run.
def relspec_child(exe, request, out, err, report)
  args, chdir, env = request
  $stdin.reopen(File::NULL)
  $stdout.reopen(out)
  $stderr.reopen(err)
  [out, err].each(&:close)
  ENV.replace(env)
  # the forked child is the run: the working folder is its own, as with spawn(chdir:)
  Dir.chdir(chdir)
  at_exit { File.write(report, File.read("/proc/self/status")[/^VmHWM:\s+(\d+)/, 1].to_s) }
  $PROGRAM_NAME = exe
  ARGV.replace(args)
  load exe
end

def serve(connection, exe, report_dir)
  out = connection.recv_io
  err = connection.recv_io
  request = PreloadedRelspec.read_message(connection)
  report = File.join(report_dir, "rss-#{Process.pid}")
  child = fork do
    connection.close
    relspec_child(exe, request, out, err, report)
  end
  [out, err].each(&:close)
  _, status = Process.wait2(child)
  rss = File.read(report).to_i if File.file?(report)
  FileUtils.rm_f(report)
  PreloadedRelspec.write_message(connection, [child, status.exitstatus, status.termsig, rss])
end

server = UNIXServer.new(socket_path)
# the connections' processes are nobody's to wait for
Signal.trap("CHLD", "IGNORE")
parent = Process.ppid
loop do
  ready = server.wait_readable(5)
  # a test process that was killed cannot stop its server
  exit!(0) if Process.ppid != parent
  next unless ready

  connection = server.accept
  fork do
    server.close
    Signal.trap("CHLD", "DEFAULT")
    serve(connection, exe, File.dirname(socket_path))
    exit!(0)
  end
  connection.close
end
