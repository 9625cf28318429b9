# frozen_string_literal: true

require "fileutils"
require "tmpdir"
require_relative "rock_workspace"
require_relative "fixtures_needed"

# The preamble of every scenario on the real Rock workspace: one fresh
# workspace per example group (the examples of a group may read it, never
# each other's changes to it: groups that change it do so in their own
# before(:all), after this one). @dir is the group's folder, @workspace the
# RockWorkspace in @dir/ws.
RSpec.shared_context "a real Rock workspace" do
  before(:all) do
    need_fixture(RockWorkspace.available?, RockWorkspace.skip_reason)

    @dir = Dir.mktmpdir("relspec-rock")
    @workspace = RockWorkspace.new(File.join(@dir, "ws"))
    @workspace.create
  end

  after(:all) { FileUtils.rm_rf(@dir) if @dir }
end
