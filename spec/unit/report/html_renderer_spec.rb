# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/report/page"
require "relspec/report/html_renderer"

RSpec.describe Relspec::Report::HtmlRenderer do
  R = Relspec::Report

  def cell(package, **fields)
    R::Cell.new(package: package, source: "rock-#{package.tr('/<>&"', 'x')}", decision: "build", version: "1.0-1",
                **fields).freeze
  end

  # A page whose every text is hostile: names, versions, log lines.
  let(:evil) { %(<script>alert("x")</script>&') }
  let(:page) do
    cells = [cell("base/types", status: "failed", duration: 3.25, log: "logs/bookworm-amd64/rock-types.log",
                                first_error: "error: #{evil}", causes: ["blacklisted by #{evil}"]),
             cell("drivers/io#{evil}", status: "skipped", blocked_by: ["rock-basextypes"], reason: "x"),
             cell("base/cmake", decision: "inherit", from: "base#{evil}", version: "1.0#{evil}")]
    view = R::TargetView.new(target: "bookworm/amd64", backend: "host", cells: cells,
                             totals: { "inherit" => 1, "build" => 2, "failed" => 1, "skipped" => 1, "built" => 0 },
                             build_seconds: 3.25, blockers: [R::Blocker.new(source: "rock-basextypes", package: "base/types",
                                                                            blocked: ["drivers/io#{evil}"])],
                             critical_path: [R::Step.new(source: "rock-basextypes", duration: 3.25)],
                             changes: [R::Change.new(package: evil, change: "added", new: "build 1.0")])
    R::Page.new(release: "child#{evil}", ancestor: "base", targets: [view])
  end
  let(:html) { described_class.new.render(page) }

  it "escapes every text of the page: no markup of the inputs reaches it" do
    expect(html).not_to include("<script")
    expect(html.scan("&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;&amp;&#39;").size).to eq(11) # title, heading, names, version, release, error, chain, change
  end

  it "is one file a phone and a printer read: viewport, its own style, nothing from elsewhere" do
    expect(html).to start_with("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n" \
                               "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">")
    expect(html).to include("@media (max-width: 600px)", "@media print")
    expect(html.scan(/(?:href|src)="([^"]*)"/).flatten).to all(match(%r{\A(#|logs/)}))
    expect(html).not_to match(/<link|<img|@import|url\(/)
  end

  it "shows the failure's first error with a link to its log, the skipped naming the failure, the inherited their release" do
    expect(html).to include("<pre class=\"error\">error: &lt;script&gt;")
    expect(html).to include("<a href=\"logs/bookworm-amd64/rock-types.log\">whole log</a>")
    expect(html).to include("skipped</span> <span class=\"muted\">because of base/types</span>")
    expect(html).to include("inherited from <b>base&lt;script&gt;")
    expect(html).to include("<li><b>base/types</b> blocks 1 package: drivers/io&lt;script&gt;")
    expect(html).to include("base/types (3.2 s): 3.2 s", "3.2 s of builds (host)")
    expect(html).to include("<pre>  blacklisted by &lt;script&gt;") # the chain as `relspec why` writes it
    expect(html).to include("<h3>Changes against base</h3>")
  end

  it "gives the same bytes for the same page" do
    expect(described_class.new.render(page)).to eq(html)
  end
end
