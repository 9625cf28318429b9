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
