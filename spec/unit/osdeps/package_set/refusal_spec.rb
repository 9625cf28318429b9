# frozen_string_literal: true

require_relative "../../unit_helper"
require "autoproj"
require "relspec/osdeps/package_set/refusal"

# How the package set stops autoproj (real autoproj's ConfigError).
RSpec.describe RelspecPackageSet do
  it "reads plain YAML, an empty file as the given value, and refuses anything else naming the file" do
    Dir.mktmpdir do |dir|
      path = File.join(dir, "x.yml")
      File.write(path, "a: 1\n")
      expect(described_class.read_yaml(path, {})).to eq("a" => 1)
      File.write(path, "")
      expect(described_class.read_yaml(path, [])).to eq([])
      File.write(path, "a: [\n")
      expect { described_class.read_yaml(path, {}) }
        .to raise_error(Autoproj::ConfigError, /\Arelspec package set: #{Regexp.escape(path)}: is not plain YAML \(/)
    end
  end
end
