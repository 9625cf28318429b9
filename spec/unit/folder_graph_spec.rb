# frozen_string_literal: true

require_relative "unit_helper"
require "tsort"
require "fileutils"

# lib/relspec/ is one folder per stage, the stage's entry beside it
# (docs/ARCHITECTURE.md): plan.rb and plan/ are one node, and so is every
# other top-level file. A require_relative from one node into another is an
# edge; the graph must have no cycle, so that each stage can be read (and
# changed) knowing only the stages below it (issue 47: catalog<->debian,
# abi<->builder).
RSpec.describe "the folder graph of lib/relspec/", :tmpdir do
  # {node => {node => [file requiring it, …]}} of the tree under +root+.
  def folder_graph(root)
    node = ->(relative) { relative.split("/").first.delete_suffix(".rb") }
    Dir.glob("**/*.rb", base: root).sort.each_with_object(Hash.new { |hash, key| hash[key] = {} }) do |file, graph|
      from = node.call(file)
      File.read(File.join(root, file)).scan(/^\s*require_relative\s+["']([^"']+)["']/).flatten.each do |required|
        path = File.expand_path(required, File.dirname(File.join(root, file)))
        to = node.call(path.delete_prefix("#{File.expand_path(root)}/"))
        (graph[from][to] ||= []) << file unless from == to
      end
    end
  end

  # The cycles: strongly connected components of more than one node, each
  # with the requires that make it.
  def cycles(graph)
    nodes = (graph.keys + graph.values.flat_map(&:keys)).uniq.sort
    components = TSort.strongly_connected_components(->(&each) { nodes.each(&each) },
                                                     ->(from, &each) { graph.fetch(from, {}).keys.sort.each(&each) })
    components.select { |component| component.size > 1 }.map do |component|
      component.sort.flat_map do |from|
        (graph.fetch(from, {}).keys & component).map { |to| "#{from} -> #{to} (#{graph[from][to].first})" }
      end
    end
  end

  it "has no cycle" do
    root = File.expand_path("../../lib/relspec", __dir__)
    graph = folder_graph(root)
    expect(graph.keys).to include("plan", "debian", "catalog", "builder", "abi")
    expect(cycles(graph)).to eq([])
  end

  it "finds a cycle through a stage's entry file" do
    files = { "a.rb" => 'require_relative "a/x"', "a/x.rb" => 'require_relative "../b/y"',
              "b/y.rb" => 'require_relative "../c"', "c.rb" => 'require_relative "a"' }
    files.each do |path, text|
      FileUtils.mkdir_p(File.dirname(File.join(@dir, path)))
      File.write(File.join(@dir, path), "#{text}\n")
    end
    expect(cycles(folder_graph(@dir))).to eq([["a -> b (a/x.rb)", "b -> c (b/y.rb)", "c -> a (c.rb)"]])
  end
end
