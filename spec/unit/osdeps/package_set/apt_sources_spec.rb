# frozen_string_literal: true

require_relative "../../unit_helper"
require "autoproj"
require "relspec/osdeps/package_set/apt_sources"

# The apt sources of a release's lineage, made from data/apt.yml and checked
# (Osdeps::Trust) before anything is written; only the reading runs here
# (install writes /etc/apt).
RSpec.describe RelspecPackageSet::AptSources do
  def sources(apt, lineage: ["r"])
    Dir.mktmpdir do |dir|
      FileUtils.mkdir_p(File.join(dir, "data", "keys"))
      File.write(File.join(dir, "data", "keys", "r.gpg"), "key bytes")
      File.write(File.join(dir, "data", "apt.yml"), YAML.dump(apt))
      return described_class.new(File.join(dir, "data"), lineage, "bookworm", File.join(dir, "state"))
                            .instance_variable_get(:@releases)
    end
  end

  it "makes one source per release, signed by the shipped key or trusted when the entry says so" do
    keyed, trusted = sources({ "r" => { "url" => "http://h/r", "key" => "keys/r.gpg" },
                               "p" => { "url" => "http://h/p", "trusted" => true } }, lineage: %w[r p])
    expect(keyed).to include(list: "/etc/apt/sources.list.d/relspec-r.list", key: "key bytes",
                             text: "#{described_class::HEADER}deb [signed-by=/etc/apt/keyrings/relspec-r.gpg] http://h/r bookworm main\n")
    expect(trusted[:text]).to eq("#{described_class::HEADER}deb [trusted=yes] http://h/p bookworm main\n")
  end

  it "refuses a release without an entry, an unverified one and a key outside the package set" do
    expect { sources({}) }.to raise_error(Autoproj::ConfigError, /apt\.yml: r: has no entry\z/)
    expect { sources({ "r" => { "url" => "http://h/r" } }) }.to raise_error(Autoproj::ConfigError, /r: has no key and does not say trusted/)
    expect { sources({ "r" => { "url" => "http://h/r", "key" => "keys/x.gpg" } }) }
      .to raise_error(Autoproj::ConfigError, %r{r: the key keys/x\.gpg is not a file of the package set\z})
  end
end
