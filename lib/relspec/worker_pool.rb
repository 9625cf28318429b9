# frozen_string_literal: true

module Relspec
  # The one thread pool of relspec: runs a block over a list of items on up
  # to +size+ threads (compile's emission, the Launchpad questions). A block
  # that raises does not stop the others: every item is worked on, and the
  # first error is raised in the calling thread once all threads ended, so
  # that errors become messages where the CLI catches them.
  #
  # The build scheduler has its own dispatch: it starts a package when its
  # dependencies are done, which a fixed list of items cannot express.
  class WorkerPool
    attr_reader :size

    def initialize(size)
      @size = [size.to_i, 1].max
    end

    # Calls the block once per item (never nil: nil ends a worker), from up
    # to #size threads; returns +items+.
    def each(items, &work)
      queue = Queue.new
      items.each { |item| queue << item }
      queue.close
      failures = []
      lock = Mutex.new
      Array.new([@size, items.size].min) do
        Thread.new { drain(queue, failures, lock, &work) }
      end.each(&:join)
      raise failures.first unless failures.empty?

      items
    end

    private

    def drain(queue, failures, lock)
      Thread.current.report_on_exception = false
      while (item = queue.pop)
        begin
          yield item
        rescue StandardError => e # raised again by #each, in the calling thread
          lock.synchronize { failures << e }
        end
      end
    end
  end
end
