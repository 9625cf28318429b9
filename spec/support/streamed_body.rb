# frozen_string_literal: true

# A WEBrick answer whose body never ends on its own: +piece+ written again
# and again (after +pause+ seconds each), for a client's deadlines and size
# caps. It stops when the client hangs up, or after +limit+ seconds so that
# no test leaves a thread behind for long.
module StreamedBody
  module_function

  def attach(response, piece, pause, limit: 60)
    response.chunked = true
    response.body = proc do |out|
      stop_at = Process.clock_gettime(Process::CLOCK_MONOTONIC) + limit
      while Process.clock_gettime(Process::CLOCK_MONOTONIC) < stop_at
        out.write(piece) # (WEBrick 1.9's ChunkedWrapper#<< is broken)
        sleep(pause) if pause.positive?
      end
    rescue IOError, SystemCallError
      nil # the client hung up: what the tests expect
    end
  end
end
