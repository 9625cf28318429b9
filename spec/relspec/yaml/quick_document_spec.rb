# frozen_string_literal: true

require "spec_helper"
require "relspec/yaml/quick_document"

# QuickDocument must give exactly LocatedDocument's data, or nothing (the
# reader then uses LocatedDocument, which says where the problem is).
RSpec.describe Relspec::Yaml::QuickDocument do
  def project_root = File.expand_path("../../..", __dir__)

  def located(text)
    Relspec::Yaml::LocatedDocument.parse(text, file: "x.yml")
  end

  it "gives LocatedDocument's data for every lock and spec of the project that LocatedDocument reads cleanly" do
    files = Dir.glob(File.join(project_root, "{releases,specs,examples,spec/fixtures}", "**", "*.yml"))
    compared = files.count do |file|
      text = File.binread(file)
      reference = located(text)
      next false unless reference.ok?

      quick = described_class.parse(text)
      expect(quick).not_to be_nil, "#{file} was not read quickly"
      expect(quick.data).to eq(reference.data), "#{file} reads differently"
      true
    end
    expect(compared).to be > 20
  end

  it "keeps the text of scalars that are not text, as LocatedDocument#raw does" do
    text = "v: 20.10\nq: '4.8'\nn: [1.10, 7]\nrelspec_lock: 2\n"
    quick = described_class.parse(text)
    reference = located(text)
    [["v"], ["n", 0], ["n", 1], ["relspec_lock"]].each do |path|
      expect(quick.raw(path)).to eq(reference.raw(path)), path.inspect
    end
    expect(quick.data).to eq("v" => 20.1, "q" => "4.8", "n" => [1.1, 7], "relspec_lock" => 2)
  end

  it "reads dates, symbols and empty values as LocatedDocument does" do
    text = "d: 2020-01-01\nt: 2020-01-01T00:00:00Z\ns: :sym\ne:\nl: []\nm: {}\nb: yes\n"
    expect(described_class.parse(text).data).to eq(located(text).data)
  end

  {
    "a syntax error" => "a: [1, 2\n",
    "a duplicate key" => "a: 1\nb: 2\na: 3\n",
    "a list as key" => "? [a]\n: 1\n",
    "a tag" => "a: !!binary aGk=\n",
    "an anchor" => "a: &x 1\nb: *x\n",
    "a second document" => "a: 1\n---\nb: 2\n",
    "invalid UTF-8" => "a: \xFF\n".b,
    "too deep a nesting" => "#{'[' * 70}#{']' * 70}\n"
  }.each do |what, text|
    it "leaves #{what} to LocatedDocument" do
      expect(described_class.parse(text)).to be_nil
    end
  end
end
