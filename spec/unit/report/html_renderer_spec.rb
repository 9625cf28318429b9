# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/report/page"
require "relspec/report/html_renderer"
require "relspec/report/abi_summary"

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

  context "with two targets" do
    let(:arm) do
      abi = R::AbiSummary.new(counts: { "unchanged" => 2, "compatible" => 0, "changed" => 1, "incompatible" => 1, "new" => 0 },
                              listed: [R::AbiLibrary.new(package: "base/types", library: "lib#{evil}.so",
                                                         verdict: "incompatible", against: "base"),
                                       R::AbiLibrary.new(package: "drivers/io", library: "libio.so", verdict: "changed",
                                                         against: "base")])
      R::TargetView.new(target: "jammy/arm64", backend: "host", cells: [cell("base/types", status: "built", duration: 1.5),
                                                                        cell("a/only-arm", status: "not built yet")],
                        totals: { "build" => 2, "built" => 1 }, build_seconds: 1.5, blockers: [],
                        critical_path: [R::Step.new(source: "rock-basextypes", duration: 1.5)], abi: abi)
    end
    let(:two) { described_class.new.render(R::Page.new(release: "child", ancestor: "base", targets: [page.targets.first, arm])) }
    let(:rows) { two[%r{<table class="matrix">.*?</table>}m].scan(%r{<tr>.*?</tr>}) }

    it "shows one matrix: a row per package, a column per target, each cell naming its target on a phone" do
      expect(two.scan('<table class="matrix">').size).to eq(1)
      expect(rows.first).to eq('<tr><th>Package</th><th><a href="#target-bookworm-amd64">bookworm/amd64</a></th>' \
                               '<th><a href="#target-jammy-arm64">jammy/arm64</a></th></tr>')
      expect(rows.drop(1).map { |row| row[%r{\A<tr><td>([^<]*)</td>}, 1] })
        .to eq(["a/only-arm", "base/cmake", "base/types", "drivers/io&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;&amp;&#39;"])
      types = rows.find { |row| row.start_with?("<tr><td>base/types</td>") }
      expect(types).to include('<td data-label="bookworm/amd64"><div>built here</div><div><code>1.0-1</code></div>' \
                               '<div><a href="#target-bookworm-amd64-rock-basextypes"><span class="badge failed">failed</span>' \
                               '</a> <span class="muted">3.2 s</span></div></td>')
      expect(types).to include('<td data-label="jammy/arm64"><div>built here</div><div><code>1.0-1</code></div>' \
                               '<div><span class="badge built">built</span> <span class="muted">1.5 s</span></div></td>')
      expect(rows.find { |row| row.start_with?("<tr><td>a/only-arm</td>") }).to include("<tr><td>a/only-arm</td><td></td>")
      expect(two).to include("td:empty { display: none; }") # a target without the package takes no room on a phone
    end

    it "keeps each target's totals and critical path" do
      expect(two).to include('<h2 id="target-jammy-arm64">jammy/arm64</h2>', "1.5 s of builds (host)",
                             "base/types (1.5 s): 1.5 s", "base/types (3.2 s): 3.2 s")
    end

    it "sums up the ABI verdicts of a target that has them, escaped, and says nothing for one that has none" do
      expect(two.scan("<h3>ABI against").size).to eq(1)
      expect(two).to include("<p class=\"totals\"><span>2 unchanged</span> <span>1 changed</span> <span>1 incompatible</span></p>")
      expect(two).to include('<li><span class="badge incompatible">incompatible</span> <code>lib&lt;script&gt;')
      expect(two).to include('<code>libio.so</code> (drivers/io) <span class="muted">against base</span></li>')
    end

    it "says why the verdicts are missing when they could not be computed" do
      arm.abi = R::AbiSummary.failed("abidiff <x> failed")
      expect(two).to include("<p class=\"muted\">not computed: abidiff &lt;x&gt; failed</p>")
    end
  end

  it "gives the same bytes for the same page" do
    expect(described_class.new.render(page)).to eq(html)
  end
end
