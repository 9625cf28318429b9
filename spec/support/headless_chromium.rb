# frozen_string_literal: true

require "open3"
require "tmpdir"
require "fileutils"

# Debian's Chromium, headless, in a network namespace of its own (`unshare
# -n`: only a loopback that is down), so that a page that needs anything
# from the network shows it by missing it. As root it needs --no-sandbox;
# the other flags keep it from calling home. Each run has a fresh profile.
module HeadlessChromium
  BINARY = "chromium"
  FLAGS = %w[--headless --no-sandbox --disable-gpu --disable-background-networking --no-first-run
             --disable-component-update --disable-sync --disable-dev-shm-usage].freeze

  module_function

  # The DOM of the file at +path+ after it loaded, serialized.
  def dump_dom(path)
    run("--dump-dom", "file://#{File.expand_path(path)}")
  end

  # A PNG of the file at +path+ in a window of +width+ x +height+ pixels.
  def screenshot(path, png, width:, height:)
    run("--window-size=#{width},#{height}", "--screenshot=#{File.expand_path(png)}", "file://#{File.expand_path(path)}")
    raise "chromium wrote no #{png}" unless File.size?(png)
  end

  def run(*args)
    Dir.mktmpdir("relspec-chromium") do |profile|
      output, errors, status = Open3.capture3("unshare", "-n", BINARY, *FLAGS, "--user-data-dir=#{profile}", *args)
      raise "chromium #{args.join(' ')} failed: #{errors}" unless status.success?

      output
    end
  end
end
