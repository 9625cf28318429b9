# frozen_string_literal: true

require "relspec/release_specs/distribution"

RSpec.describe Relspec::ReleaseSpec::Distributions do
  describe ".builtin" do
    it "is every built-in distribution without a list, the named ones in the order named" do
      expect(described_class.builtin(nil).keys).to include("bionic", "bookworm", "noble", "trixie")
      expect(described_class.builtin("trixie, bookworm, bionic").keys).to eq(%w[trixie bookworm bionic])
    end

    it "refuses an unknown name, naming the known ones" do
      expect { described_class.builtin("bookworm,duke") }
        .to raise_error(Relspec::InvalidOption, /\Aunknown distribution "duke" \(known: xenial, bionic,.*, trixie\)/)
    end
  end

  # Debian 13's facts: what autoproj reads of its /etc/os-release
  # (VERSION_ID="13", VERSION="13 (trixie)"), its ruby-defaults (3.3) and
  # debhelper 13.24 (compat 13; 14 is still experimental there).
  describe "trixie" do
    let(:trixie) { described_class::BUILTIN.fetch("trixie") }

    it "is keyed in osdeps as autoproj names Debian 13, with its own Ruby and debhelper compat" do
      expect([trixie.type, trixie.labels, trixie.osdeps_type_key, trixie.osdeps_labels_key])
        .to eq(["debian", %w[13 trixie default], "debian", "13,trixie"])
      expect([trixie.ruby, trixie.ruby_version_keyword, trixie.debhelper_compat]).to eq(["3.3", "ruby33", 13])
      # ruby3.3 3.3.8-2: grape 4.1.0 (Ruby >= 3.3.1) runs there
      expect([trixie.ruby_release, described_class::BUILTIN.fetch("bookworm").ruby_release]).to eq(%w[3.3.8 3.1.2])
      expect(trixie.ruby_install_dirs("amd64")).to eq(%w[lib/ruby/3.3.0 lib/x86_64-linux-gnu/ruby/3.3.0])
      expect(trixie.ruby_executable).to eq("/usr/bin/ruby3.3")
    end

    it "names the ruby package's /usr/bin/ruby for a distribution whose Ruby is not known" do
      duke = described_class.with_overrides("duke" => { "type" => "debian", "labels" => %w[15 duke] }).fetch("duke")
      expect(duke.ruby_executable).to eq("/usr/bin/ruby")
    end

    it "keeps its built-in facts when a spec only adds an archive" do
      own = described_class.with_overrides("trixie" => { "archive" => { "host" => true } }).fetch("trixie")
      expect([own.labels, own.ruby, own.ruby_release, own.debhelper_compat, own.archive.host?])
        .to eq([%w[13 trixie default], "3.3", "3.3.8", 13, true])
    end
  end

  it "does not build in Debian testing, which autoproj cannot tell from sid" do
    expect(described_class::BUILTIN.keys).not_to include("forky", "sid")
  end
end
