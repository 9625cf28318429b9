# frozen_string_literal: true

module Relspec
  # relspec's folder in the XDG cache ($XDG_CACHE_HOME, else ~/.cache), read
  # from the environment and never written to it; nil when there is no home.
  module CacheDir
    def self.for(kind)
      base = ENV.fetch("XDG_CACHE_HOME", nil)
      base = File.join(Dir.home, ".cache") if base.nil? || base.empty?
      File.join(base, "relspec", kind)
    rescue ArgumentError
      nil
    end
  end
end
