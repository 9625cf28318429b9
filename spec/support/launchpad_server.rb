# frozen_string_literal: true

require "json"
require "uri"
require "webrick"

# A WEBrick server on 127.0.0.1 answering like Launchpad's web service
# (api.launchpad.net/1.0) for `Archive.getPublishedBinaries` on
# /1.0/ubuntu/+archive/primary. The answers follow the shapes Launchpad
# documents: a collection is a JSON object with `start`, `total_size`,
# `entries` and, when more pages follow, `next_collection_link` (the URL of
# the next page, with ws.start/ws.size; help.launchpad.net/API/Hacking,
# "Collections"); each entry is a binary_package_publishing_history
# (api.launchpad.net/+apidoc/1.0.html#binary_package_publishing_history) with
# binary_package_name, binary_package_version, display_name,
# distro_arch_series_link, architecture_specific, component_name, pocket,
# status, self_link and resource_type_link. A distro_arch_series that does
# not exist is answered 404 with a plain-text body, as Launchpad does for an
# object it cannot find.
#
# Faults per binary name: a list of answers to give first (503, [429,
# retry_after], [:slow, seconds]); every request is logged, and the highest
# number of requests in flight at once is kept.
class LaunchpadServer
  attr_reader :requests, :max_in_flight

  # +published+: {"series/arch" => [binary names]}; +page_size+: entries
  # per page; +delay+: seconds each answer takes (to see concurrency).
  def initialize(published, page_size: 75, delay: 0)
    @published = published
    @page_size = page_size
    @delay = delay
    @faults = Hash.new { |hash, key| hash[key] = [] }
    @requests = []
    @in_flight = 0
    @max_in_flight = 0
    @lock = Mutex.new
    @server = WEBrick::HTTPServer.new(BindAddress: "127.0.0.1", Port: 0, Logger: WEBrick::Log.new(File::NULL),
                                      AccessLog: [], MaxClients: 100)
    @server.mount_proc("/") { |request, response| serve(request, response) }
    @thread = Thread.new { @server.start }
  end

  def base
    "http://127.0.0.1:#{@server.config[:Port]}/1.0"
  end

  def fail(name, *answers)
    @faults[name].concat(answers)
  end

  # The binary names asked for, one per request.
  def names_asked
    @lock.synchronize { @requests.map { |query| query["binary_name"] } }
  end

  def stop
    @server.shutdown
    @thread.join(5)
  end

  private

  def serve(request, response)
    query = URI.decode_www_form(request.query_string.to_s).to_h
    enter(query)
    sleep(@delay) if @delay.positive?
    fault = @lock.synchronize { @faults[query["binary_name"]].shift }
    return if fault && inject(fault, response)

    collection(request, query, response)
  ensure
    @lock.synchronize { @in_flight -= 1 }
  end

  def enter(query)
    @lock.synchronize do
      @requests << query
      @in_flight += 1
      @max_in_flight = [@max_in_flight, @in_flight].max
    end
  end

  def inject(fault, response)
    code, seconds = Array(fault)
    case code
    when :slow
      sleep(seconds)
      false
    when :drip, :endless
      # not Launchpad's behaviour: a hostile or broken server (a body that
      # comes one byte at a time, or never ends), for the client's bounds
      stream(response, code == :drip ? "{" : "x" * 65_536, code == :drip ? 0.05 : 0)
      true
    when 429
      response.status = 429
      response["Retry-After"] = seconds.to_s
      true
    else
      response.status = code
      response.body = "Service unavailable"
      true
    end
  end

  def stream(response, piece, pause)
    response.status = 200
    response["Content-Type"] = "application/json"
    StreamedBody.attach(response, piece, pause, limit: 30)
  end

  def collection(_request, query, response)
    series_link = query["distro_arch_series"].to_s
    series = series_link.delete_prefix("#{base}/ubuntu/")
    unless query["ws.op"] == "getPublishedBinaries" && @published.key?(series)
      response.status = 404
      response["Content-Type"] = "text/plain"
      response.body = "Object: <Distribution 'Ubuntu' (ubuntu)>, name: '#{series.split('/').first}'"
      return
    end

    name = query["binary_name"].to_s
    names = @published.fetch(series).select { |candidate| query["exact_match"] == "true" ? candidate == name : candidate.include?(name) }
    start = Integer(query.fetch("ws.start", "0"))
    size = Integer(query.fetch("ws.size", @page_size.to_s))
    page = names[start, size] || []
    body = { "start" => start, "total_size" => names.size,
             "resource_type_link" => "#{base}/#binary_package_publishing_history-page-resource",
             "entries" => page.map { |binary| entry(binary, series, series_link) } }
    if start + size < names.size
      body["next_collection_link"] = "#{base}/ubuntu/+archive/primary?" +
                                     URI.encode_www_form(query.merge("ws.start" => (start + size).to_s, "ws.size" => size.to_s))
    end
    response["Content-Type"] = "application/json"
    response.body = JSON.generate(body)
  end

  def entry(binary, series, series_link)
    codename, arch = series.split("/")
    {
      "self_link" => "#{base}/ubuntu/+archive/primary/+binarypub/#{binary.hash.abs}",
      "resource_type_link" => "#{base}/#binary_package_publishing_history",
      "binary_package_name" => binary, "binary_package_version" => "1.0-1",
      "display_name" => "#{binary} 1.0-1 in #{codename} #{arch}", "distro_arch_series_link" => series_link,
      "architecture_specific" => true, "component_name" => "main", "section_name" => "devel",
      "pocket" => "Release", "status" => "Published"
    }
  end
end
