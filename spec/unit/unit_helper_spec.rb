# frozen_string_literal: true

require_relative "unit_helper"
require "open3"

RSpec.describe "the unit layer's guard" do
  it "refuses child processes, however they are started" do
    expect { Open3.capture2("true") }.to raise_error(UnitLayer::ChildProcess, /child process/)
    expect { system("true") }.to raise_error(UnitLayer::ChildProcess)
    expect { `true` }.to raise_error(UnitLayer::ChildProcess)
  end
end
