# frozen_string_literal: true

require "webrick"
require "logger"

# A real HTTP server on 127.0.0.1 serving a folder, for repositories read
# over the network. Paths can be made to answer 404 or 500, or to stall, and
# every request is counted. The folder is also served below any first path
# segment (/x/dists/… is /dists/…, unless the folder has x/dists/…), so one
# server can play several hosts.
class HttpServer
  attr_reader :requests

  # +port+: a free one unless given (the port a published package set names).
  def initialize(root, port: 0)
    @root = root
    @requests = []
    @faults = {}
    @server = WEBrick::HTTPServer.new(BindAddress: "127.0.0.1", Port: port, DocumentRoot: root,
                                      Logger: WEBrick::Log.new(File::NULL), AccessLog: [])
    @server.mount_proc("/") { |request, response| serve(request, response) }
    @thread = Thread.new { @server.start }
  end

  def url
    "http://127.0.0.1:#{@server.config[:Port]}"
  end

  # +fault+: 404, 500, :stall (no answer for +seconds+), :redirect (302
  # to the same path below /moved/), :no_last_modified (the file without
  # a Last-Modified header, as forges' generated archives) or :unavailable_once
  # (503 the first time a path is asked, then the file), for paths
  # matching +pattern+.
  def fail(pattern, fault, seconds: 5)
    @faults[pattern] = [fault, seconds]
  end

  def stop
    @server.shutdown
    @thread.join(5)
  end

  private

  def serve(request, response)
    path = request.path
    @requests << path
    fault, seconds = @faults.find { |pattern, _| pattern.match?(path) }&.last
    case fault
    when 404, 500 then response.status = fault
    when :stall then sleep(seconds)
    when :redirect then response.set_redirect(WEBrick::HTTPStatus::Found, "#{url}/moved#{path}")
    when :unavailable_once then fault = @requests.count(path) == 1 ? 503 : nil
    end
    response.status = 503 if fault == 503
    return if fault && fault != :no_last_modified

    file = file_for(path)
    if file
      response.body = File.binread(file)
      # as a web server serving files does: archive imports are versioned by it
      response["Last-Modified"] = File.mtime(file).httpdate unless fault == :no_last_modified
    else
      response.status = 404
    end
  end

  # The served file of +path+: the folder's own, else the one below its
  # first segment; nil when there is none.
  def file_for(path)
    path = path.delete_prefix("/moved")
    [path, path.sub(%r{\A/[^/]+/(?=dists/)}, "/")].map { |candidate| File.join(@root, candidate) }.find { |file| File.file?(file) }
  end
end
