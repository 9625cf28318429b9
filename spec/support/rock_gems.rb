# frozen_string_literal: true

require "digest"
require "fileutils"
require "net/http"
require_relative "gem_builder"

# The third-party gems the Rock fixture needs, as real .gem files where the
# machine can have them: facets 3.1.0 (utilrb requires facets/kernel/constant,
# which facets 4 dropped) and rice 3.0.0 (base/types' Ruby bindings). Each is
# downloaded once, by its address, from the RubyGems source this machine
# reaches, checked against its pinned SHA-256, and kept in the project's
# tmp/gems (git-ignored, never committed) for later runs. Without a source, a
# stand-in facets 3.1.0 is built locally with the two files utilrb loads; rice
# has no stand-in.
#
# Not `gem fetch`: it first parses the whole RubyGems index (87 MB, 30 s of
# CPU on an idle machine), and under CI's load it ran past any sane deadline.
module RockGems
  CACHE = File.expand_path("../../tmp/gems", __dir__)
  FETCH_TIMEOUT = 60 # seconds for one download
  FETCH_ATTEMPTS = 3
  REDIRECTS = 3
  SHA256 = {
    "facets-3.1.0.gem" => "7834a68824efbb35380ed7f6f590e01fb9a31a9466e317210e8803f72813c345",
    "rice-3.0.0.gem" => "df7708498dcf41fba067c940bf40840c0b019fb75bd3aca7a8938904c6695ae1",
    # bin/toolchain: what Rock's osdeps ask of rake-compiler (rtt_typelib, typelib)
    "rake-compiler-0.8.3.gem" => "37cfbbff2fa330ac2eee2947a505ae537df4394a64001588493904d419c98e1f"
  }.freeze

  module_function

  # Puts facets-3.1.0.gem into +dir+; returns :rubygems or :stand_in.
  def facets(dir)
    return :rubygems if provide(dir, "facets", "3.1.0")

    GemBuilder.build(dir, "facets", "3.1.0", files: STAND_IN_FACETS)
    :stand_in
  end

  # Puts rice-3.0.0.gem (the last Rice 3, as Rock's rice<4.0.0 asks) into
  # +dir+; false when it cannot be had: no stand-in can replace a C++
  # library that base/types' bindings compile against.
  def rice(dir)
    provide(dir, "rice", "3.0.0")
  end

  # Puts <name>-<version>.gem into +dir+ (one of SHA256's); false when it
  # cannot be had.
  def provide(dir, name, version)
    FileUtils.mkdir_p(dir)
    cached = fetch(name, version)
    FileUtils.cp(cached, dir) if cached
    !cached.nil?
  end

  def fetch(name, version)
    file = "#{name}-#{version}.gem"
    path = File.join(CACHE, file)
    return path if File.file?(path)

    FileUtils.mkdir_p(CACHE)
    FETCH_ATTEMPTS.times do |attempt|
      body = download(URI.join(Gem.sources.first.uri.to_s, "gems/#{file}"))
      if body && Digest::SHA256.hexdigest(body) == SHA256.fetch(file)
        File.binwrite("#{path}.part", body)
        File.rename("#{path}.part", path)
        return path
      end
      sleep(2 * (attempt + 1))
    end
    nil
  end

  def download(uri, redirects = REDIRECTS)
    response = Net::HTTP.start(uri.host, uri.port, use_ssl: uri.scheme == "https",
                                                   open_timeout: FETCH_TIMEOUT, read_timeout: FETCH_TIMEOUT) do |http|
      http.get(uri.request_uri)
    end
    return response.body if response.is_a?(Net::HTTPSuccess)
    return download(URI.join(uri.to_s, response["location"]), redirects - 1) if response.is_a?(Net::HTTPRedirection) && redirects.positive?

    nil
  rescue SystemCallError, IOError, Timeout::Error, OpenSSL::SSL::SSLError, SocketError
    nil
  end

  # What utilrb/logger uses of facets 3.1.0, written for the stand-in.
  STAND_IN_FACETS = {
    "lib/facets/kernel/constant.rb" => <<~RUBY,
      module Kernel
        # the constant a "A::B" path names
        def constant(path)
          path.to_s.split("::").reject(&:empty?).inject(Object) { |scope, name| scope.const_get(name) }
        end
      end
    RUBY
    "lib/facets/module/spacename.rb" => <<~RUBY
      class Module
        # "A::B" for A::B::C
        def spacename
          name[0...(name.rindex("::") || 0)]
        end
      end
    RUBY
  }.freeze
end
