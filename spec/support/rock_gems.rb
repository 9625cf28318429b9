# frozen_string_literal: true

require "fileutils"
require "open3"
require_relative "gem_builder"

# The third-party gems the Rock fixture needs, as real .gem files where the
# machine can have them: facets 3.1.0 (utilrb requires facets/kernel/constant,
# which facets 4 dropped) and rice 3.0.0 (base/types' Ruby bindings). `gem fetch` gets it once from the RubyGems source
# this machine reaches; it is kept in the project's tmp/gems (git-ignored,
# never committed) for later runs. Without a source, a stand-in facets 3.1.0
# is built locally with the two files utilrb loads; rice has no stand-in.
module RockGems
  CACHE = File.expand_path("../../tmp/gems", __dir__)
  FETCH_TIMEOUT = 60 # seconds for one `gem fetch`
  FETCH_ATTEMPTS = 3 # the registry copy served here once failed one fetch in a CI run and answered the next minute

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

  def provide(dir, name, version)
    FileUtils.mkdir_p(dir)
    cached = fetch(name, version)
    FileUtils.cp(cached, dir) if cached
    !cached.nil?
  end

  def fetch(name, version)
    path = File.join(CACHE, "#{name}-#{version}.gem")
    return path if File.file?(path)

    FileUtils.mkdir_p(CACHE)
    FETCH_ATTEMPTS.times do
      _output, status = Open3.capture2e("timeout", FETCH_TIMEOUT.to_s, "gem", "fetch", name, "-v", version,
                                        "--platform", "ruby", chdir: CACHE)
      return path if status.success? && File.file?(path)
    end
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
