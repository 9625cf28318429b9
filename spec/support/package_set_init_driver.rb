# frozen_string_literal: true

# Runs a package set's init.rb the way autoproj does (real autoproj, a real
# Autoproj::Workspace, `load` of init.rb) once per case, each in a fork of
# one process that loaded autoproj once (loading it takes most of the time).
# Arguments: an output file, then pairs of workspace root and package set
# folder. Writes, as JSON, per case: what init.rb raised (or "ran"), whether
# /etc/apt or apt's lists changed, the osdeps autoproj received and the
# environment variables the workspace got. Used by package_set_init_spec.rb.
require "autoproj"
require "json"

APT = %w[/etc/apt/sources.list.d /etc/apt/keyrings /var/lib/apt/lists].freeze

def apt_state
  APT.to_h do |dir|
    files = Dir.glob("**/*", base: dir).reject { |path| path.start_with?("partial") || path == "lock" }.sort
    [dir, files.to_h { |path| [path, File.file?(File.join(dir, path)) ? File.mtime(File.join(dir, path)).to_f : 0] }]
  end
end

output = ARGV.shift
results = ARGV.each_slice(2).map do |root, package_set|
  reader, writer = IO.pipe
  pid = fork do
    reader.close
    ws = Autoproj::Workspace.new(root)
    Autoproj.workspace = ws
    before = apt_state
    watched = %w[LD_PRELOAD LD_LIBRARY_PATH PATH RUBYOPT]
    env_before = watched.to_h { |name| [name, ws.env.environment[name].dup] }
    outcome = begin
      Autoproj.silent { load File.join(package_set, "init.rb") }
      "ran"
    rescue Autoproj::ConfigError => e
      e.message
    end
    env = watched.to_h { |name| [name, ws.env.environment[name]] }.reject { |name, values| env_before[name] == values }
    writer.write(JSON.generate("message" => outcome, "apt_changed" => apt_state != before, "env" => env,
                               "osdeps" => ws.os_package_resolver.all_package_names.sort))
    writer.close
    exit!(0)
  end
  writer.close
  text = reader.read
  _, status = Process.wait2(pid)
  text.empty? ? { "message" => "the case's process died (#{status.inspect})" } : JSON.parse(text)
end
File.write(output, JSON.generate(results))
