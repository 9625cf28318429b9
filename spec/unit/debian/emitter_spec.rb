# frozen_string_literal: true

require "relspec/debian/emitter"
require "relspec/diagnostic"
require "relspec/location"

# Debian::Emitter's own rules (parallel emission, what is counted, how
# failures come back), in memory: the packages are stand-ins answering
# #emit and #repaired as SourcePackage does; real emission (dpkg-source,
# tar) is covered by spec/relspec/compile/.
RSpec.describe Relspec::Debian::Emitter do
  let(:package_class) do
    Struct.new(:changed, :repaired, :error) do
      def emit(_dir)
        raise error if error

        changed
      end
    end
  end

  it "sorts what was written and what was already there, and every repaired orig once" do
    done = []
    packages = [["b", package_class.new(true, ["orig1"])], ["a", package_class.new(false, [])], ["c", package_class.new(true, ["orig1"])]]
    result = described_class.new(jobs: 2, progress: ->(count, total) { done << [count, total] }).call(packages)
    expect(result.to_h).to eq(written: %w[b c], unchanged: ["a"], repaired: ["orig1"])
    expect(done.map(&:last)).to eq([3, 3, 3])
    expect(done.map(&:first).sort).to eq([1, 2, 3])
  end

  it "tries every package and raises the diagnostics of all that failed together" do
    bad = lambda do |name|
      Relspec::InvalidInput.new([Relspec::Diagnostic.error("overlay", "#{name} is broken", location: Relspec::Location.file_only(name))])
    end
    packages = [["x", package_class.new(nil, [], bad.call("x"))], ["ok", package_class.new(true, [])], ["y", package_class.new(nil, [], bad.call("y"))]]
    expect { described_class.new(jobs: 1).call(packages) }
      .to raise_error(Relspec::InvalidInput) { |error| expect(error.diagnostics.map(&:message)).to eq(["x is broken", "y is broken"]) }
  end

  it "re-raises any other error in the caller's thread" do
    packages = [["x", package_class.new(nil, [], Errno::ENOSPC.new("out"))]]
    expect { described_class.new(jobs: 3).call(packages) }.to raise_error(Errno::ENOSPC)
  end

  it "emits nothing for no packages" do
    expect(described_class.new(jobs: 0).call([]).to_h).to eq(written: [], unchanged: [], repaired: [])
  end
end
