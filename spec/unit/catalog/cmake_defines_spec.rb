# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/cmake_defines"

# The Ruby a workspace was loaded with, in a define, becomes ${ruby} (the
# target's Ruby in debian/rules): rock.core's RUBY_EXECUTABLE.
RSpec.describe Relspec::Catalog::CmakeDefines do
  it "writes the workspace's Ruby executable as ${ruby}, wherever it is a whole path" do
    expect(described_class.ruby_reference("/usr/bin/ruby3.1", "/usr/bin/ruby3.1")).to eq("${ruby}")
    expect(described_class.ruby_reference("/usr/bin/ruby3.1 -w;/usr/bin/ruby3.1", "/usr/bin/ruby3.1"))
      .to eq("${ruby} -w;${ruby}")
  end

  it "keeps a longer path that only starts or ends with it, and every value when no Ruby is known" do
    expect(described_class.ruby_reference("/usr/bin/ruby3.1-extra", "/usr/bin/ruby3.1")).to eq("/usr/bin/ruby3.1-extra")
    expect(described_class.ruby_reference("/opt/usr/bin/ruby3.1", "/usr/bin/ruby3.1")).to eq("/opt/usr/bin/ruby3.1")
    expect(described_class.ruby_reference("/usr/bin/ruby3.1", nil)).to eq("/usr/bin/ruby3.1")
  end
end
