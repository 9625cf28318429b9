# frozen_string_literal: true

# What every bench needs: wall time of a block and the median of runs
# (medians, because these machines are noisy).
module Timing
  module_function

  def seconds
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    yield
    Process.clock_gettime(Process::CLOCK_MONOTONIC) - started
  end

  # The median of +runs+ timings of the block.
  def median(runs, &block)
    Array.new(runs) { seconds(&block) }.sort[runs / 2]
  end
end
