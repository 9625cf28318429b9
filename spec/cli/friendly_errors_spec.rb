# frozen_string_literal: true

require "spec_helper"
require "stringio"
require "relspec/cli/friendly_errors"

# How failures become exit statuses, in process (a real SIGINT to this
# process; the CLI tests in spec/hostile/interrupt_spec.rb send it to relspec).
RSpec.describe Relspec::CLI::FriendlyErrors do
  let(:stderr) { StringIO.new }

  def wrap(&block)
    described_class.wrap(stderr: stderr, debug: false, &block)
  end

  # An interrupt that landed in a C extension's initialisation (openssl.so)
  # is swallowed there; the error it leads to is still the interrupt.
  it "answers an error that follows a swallowed SIGINT with 'interrupted' and 130" do
    status = wrap do
      begin
        Process.kill("INT", Process.pid)
        sleep(5)
      rescue Interrupt
        nil # swallowed, as a half-initialised extension does
      end
      raise NameError, "uninitialized constant OpenSSL::SSL::TLS1_VERSION"
    end
    expect([status, stderr.string]).to eq([130, "relspec: interrupted\n"])
  end

  # Issue 34, case 15: Open3's reader threads, their stream closed under
  # them when the interrupted run ends, printed their own exception report
  # to $stderr before "interrupted".
  it "lets no thread started in the run print its own exception report when the run is interrupted" do
    reader, writer = IO.pipe
    thread = nil
    report = StringIO.new
    saved = $stderr
    begin
      $stderr = report
      status = wrap do
        thread = Thread.new { reader.read }
        sleep(0.05) until thread.status == "sleep"
        Process.kill("INT", Process.pid)
        sleep(5)
      end
      reader.close # as Open3's popen_run does when its caller unwinds
      expect { thread.join }.to raise_error(IOError)
      expect([status, stderr.string, report.string]).to eq([130, "relspec: interrupted\n", ""])
    ensure
      $stderr = saved
      writer.close
    end
  end

  it "reports the same error without a SIGINT as a bug (70), and leaves SIGINT's handler as it was" do
    before = trap("INT", "DEFAULT")
    trap("INT", before)
    status = wrap { raise NameError, "uninitialized constant X" }
    expect(status).to eq(70)
    expect(stderr.string).to start_with("relspec: internal error: NameError: uninitialized constant X\n")
    expect(trap("INT", before)).to eq(before)
  end

  it "ends quietly with 0 when the reader of stdout went away" do
    expect(wrap { raise Errno::EPIPE }).to eq(0)
    expect(stderr.string).to eq("")
  end
end
