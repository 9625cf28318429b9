# frozen_string_literal: true

require_relative "../unit_helper"
require "stringio"
require "relspec/cli/osdeps_commands"

# `relspec osdeps …` in process: one call of the use case (Relspec::Osdeps)
# per command, its result printed.
RSpec.describe Relspec::CLI::OsdepsCommands do
  def stderr_of(*args)
    err = StringIO.new
    saved = $stderr
    $stderr = err
    described_class.start(args)
    err.string
  ensure
    $stderr = saved
  end

  it "says whether osdeps index wrote releases.yml" do
    Dir.mktmpdir do |dir|
      FileUtils.mkdir_p(File.join(dir, "specs"))
      File.write(File.join(dir, "specs", "a.yml"),
                 "release: a\ntargets: { bookworm: [amd64] }\nrepository: { url: https://example.org/r/a }\n")
      path = File.join(dir, "releases", "releases.yml")
      expect(stderr_of("index", "--specs", File.join(dir, "specs"))).to eq("wrote #{path}\n")
      expect(stderr_of("index", "--specs", File.join(dir, "specs"))).to eq("unchanged #{path}\n")
    end
  end
end
