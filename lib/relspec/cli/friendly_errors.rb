# frozen_string_literal: true

require_relative "../error"
require_relative "../printable"
require_relative "interrupt_watch"

module Relspec
  module CLI
    # The one place where failures become messages for people: user errors
    # print their diagnostics, bugs print one line asking for --debug. The
    # core only raises typed errors and never prints.
    module FriendlyErrors
      EXIT_USER_ERROR = 1
      EXIT_BUG = 70
      EXIT_INTERRUPTED = 130

      # Threads never print their own exception reports: relspec's threads
      # hand their errors to the thread that joins them (WorkerPool, Open3's
      # readers), which raises them here. A report would bypass this place:
      # on SIGINT the threads ended at exit (Open3's readers, their stream
      # closed under them) printed `#<Thread:…> terminated with exception`
      # before "interrupted".
      def self.wrap(stderr:, debug:, &block)
        watch = InterruptWatch.new
        reporting = Thread.report_on_exception
        Thread.report_on_exception = debug
        outcome(stderr, debug, watch) { watch.watch(&block) }
      ensure
        Thread.report_on_exception = reporting
      end

      def self.outcome(stderr, debug, watch)
        yield
        0
      rescue Interrupt
        interrupted(stderr)
      rescue StandardError, ScriptError => e
        return interrupted(stderr) if watch.received? || interrupted?(e)

        failure(e, stderr, debug)
      end

      # Re-raised so that each kind of failure has its own rescue clause.
      def self.failure(error, stderr, debug)
        raise error
      rescue InvalidInput => e
        stderr.puts(e.diagnostics.map(&:to_s))
        stderr.puts(Summary.of(e.diagnostics))
        e.status_code
      rescue InvalidOption => e
        raise if debug

        # All of it is the command line's: a newline in a value is no line of its own.
        stderr.puts("relspec: error: #{Printable.text(e.message)}")
        e.status_code
      rescue Error => e
        raise if debug

        stderr.puts("relspec: error: #{Printable.lines(e.message)}")
        e.status_code
      rescue Errno::EPIPE # a reader that stopped (`relspec show | head`)
        0
      rescue SystemCallError => e
        raise if debug

        stderr.puts("relspec: error: #{Printable.lines(e.message.sub(/ @ \w+/, ''))}")
        EXIT_USER_ERROR
      rescue StandardError, ScriptError => e
        raise if debug

        stderr.puts("relspec: internal error: #{e.class}: #{Printable.lines(e.message)}")
        stderr.puts("This is a bug in relspec; run again with --debug to see where it happened.")
        EXIT_BUG
      end

      def self.interrupted(stderr)
        stderr.puts("relspec: interrupted")
        EXIT_INTERRUPTED
      end

      # An error raised while an interrupt was being handled (a rescue clause
      # naming a class still being loaded) is still the interrupt.
      def self.interrupted?(error)
        cause = error.cause
        cause = cause.cause until cause.nil? || cause.is_a?(Interrupt)
        !cause.nil?
      end
    end

    # "2 errors, 1 warning in specs/x.yml" lines closing a report.
    module Summary
      def self.of(diagnostics)
        errors = diagnostics.count(&:error?)
        warnings = diagnostics.size - errors
        files = diagnostics.map { |d| d.location&.file }.compact.uniq.size
        parts = [count(errors, "error")]
        parts << count(warnings, "warning") if warnings.positive?
        "#{parts.join(', ')} in #{count(files, 'file')}"
      end

      def self.count(number, noun)
        "#{number} #{noun}#{'s' unless number == 1}"
      end
    end
  end
end
