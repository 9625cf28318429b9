# frozen_string_literal: true

require "webrick"

# A real WEBrick server on 127.0.0.1 that answers every request 200 with
# +body+ (changed between examples), for clients facing a server that says
# nonsense: the hostile corpus's Launchpad and gem index cases.
class FixedAnswerServer
  attr_accessor :body

  def initialize(content_type: "application/json")
    @body = ""
    @server = WEBrick::HTTPServer.new(BindAddress: "127.0.0.1", Port: 0, Logger: WEBrick::Log.new(File::NULL), AccessLog: [])
    @server.mount_proc("/") do |_request, response|
      response["Content-Type"] = content_type
      response.body = @body
    end
    @thread = Thread.new { @server.start }
  end

  def url
    "http://127.0.0.1:#{@server.config[:Port]}"
  end

  def stop
    @server.shutdown
    @thread.join(5)
  end
end
