# frozen_string_literal: true

# Tests that need a fixture from outside the project: ../shared (the real
# Rock repositories and osdeps files) or a gem fetched from RubyGems. A
# checkout without it skips them with the reason; CI always has ../shared
# and RubyGems, so there a missing fixture is a failure, never a quiet skip.
module FixturesNeeded
  def need_fixture(available, reason)
    return if available
    raise "#{reason} (CI must run every test it claims)" if ENV["CI"]

    skip reason
  end
end
