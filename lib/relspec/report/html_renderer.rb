# frozen_string_literal: true

require "cgi"
require_relative "../plan/cause"

module Relspec
  module Report
    # The Page as one static HTML file: no script, font, style sheet or image
    # from elsewhere (it is read offline and served with the repository),
    # readable on a phone (viewport, tables that scroll sideways, nothing
    # wider than the screen) and printable. Every text of the page comes from
    # files a build wrote (package names, versions, log lines): all of it is
    # escaped, here and nowhere else.
    class HtmlRenderer
      STYLE = <<~CSS
        body { font: 15px/1.45 system-ui, sans-serif; margin: 0 auto; padding: 0 12px 24px; max-width: 72rem; color: #1b1b1b; }
        h1 { font-size: 1.5rem; margin: 16px 0 4px; } h2 { font-size: 1.25rem; margin: 28px 0 8px; border-bottom: 2px solid #ddd; }
        h3 { font-size: 1.05rem; margin: 18px 0 6px; }
        .scroll { overflow-x: auto; } table { border-collapse: collapse; width: 100%; }
        th, td { text-align: left; vertical-align: top; padding: 4px 8px; border-bottom: 1px solid #e4e4e4; }
        th { background: #f4f4f4; } td.num { text-align: right; white-space: nowrap; }
        code, pre { font: 13px/1.4 ui-monospace, monospace; } pre { white-space: pre-wrap; overflow-wrap: anywhere; margin: 4px 0; }
        .badge { display: inline-block; padding: 0 6px; border-radius: 4px; font-size: 13px; white-space: nowrap; }
        .built { background: #d9f2dc; } .failed { background: #f9d0cc; font-weight: bold; } .skipped { background: #fde8bf; }
        .not-built-yet { background: #e6e6e6; } .published { background: #d7e6f8; } .kept { background: #e3f0d0; }
        .changed { background: #fde8bf; } .incompatible { background: #f9d0cc; font-weight: bold; }
        .totals span { margin-right: 10px; white-space: nowrap; } .muted { color: #606060; }
        .error { background: #fff3f1; border-left: 4px solid #c0392b; padding: 6px 8px; margin: 6px 0 12px; }
        ol, ul { padding-left: 1.3rem; } li { margin: 2px 0; } a { color: #0b57a4; overflow-wrap: anywhere; }
        td code, td b { white-space: nowrap; }
        @media (max-width: 600px) { body { font-size: 14px; padding: 0 8px 16px; }
          td code { white-space: normal; overflow-wrap: anywhere; }
          thead { display: none; } tr { display: block; padding: 6px 0; border-bottom: 1px solid #ccc; }
          td { display: block; border: none; padding: 1px 0; } td.num { text-align: left; }
          td[data-label]::before { content: attr(data-label) ": "; color: #606060; }
          td:first-child { font-weight: bold; } td:empty { display: none; }
          .matrix td div { display: inline; margin-right: 8px; } }
        @media print { body { max-width: none; font-size: 11px; } .scroll { overflow: visible; } a { color: inherit; }
          h2 { break-after: avoid; } tr, .error { break-inside: avoid; } }
      CSS

      def render(page)
        body = [heading(page), matrix(page), *page.targets.map { |view| target(view, page) }].compact.join("\n")
        <<~HTML
          <!DOCTYPE html>
          <html lang="en">
          <head>
          <meta charset="utf-8">
          <meta name="viewport" content="width=device-width, initial-scale=1">
          <title>#{h("Release #{page.release}")}</title>
          <style>
          #{STYLE.chomp}
          </style>
          </head>
          <body>
          #{body}
          </body>
          </html>
        HTML
      end

      private

      def h(text)
        CGI.escapeHTML(text.to_s)
      end

      def heading(page)
        summary = page.targets.map do |view|
          "<li><a href=\"##{anchor(view.target)}\">#{h(view.target)}</a>: #{totals(view)}</li>"
        end
        "<h1>Release #{h(page.release)}</h1>\n<ul class=\"totals\">\n#{summary.join("\n")}\n</ul>"
      end

      def anchor(target)
        "target-#{target.tr('^a-zA-Z0-9', '-')}"
      end

      def totals(view)
        view.totals.reject { |_, count| count.zero? }.map do |name, count|
          "<span>#{count} #{h(TOTAL_WORDS.fetch(name, name))}</span>"
        end.join(" ")
      end

      TOTAL_WORDS = { "inherit" => "inherited", "build" => "built here", "system" => "from the distribution",
                      "built" => "builds ok", "failed" => "failed", "skipped" => "skipped" }.freeze

      def target(view, page)
        [
          "<h2 id=\"#{anchor(view.target)}\">#{h(view.target)}</h2>",
          "<p class=\"totals\">#{totals(view)}#{build_time(view)}</p>",
          failures(view), blocked(view), critical_path(view), abi(view), causes(view), changes(view, page)
        ].compact.join("\n")
      end

      def build_time(view)
        return "" unless view.build_seconds.positive?

        " <span class=\"muted\">#{seconds(view.build_seconds)} of builds (#{h(view.backend)})</span>"
      end

      def seconds(value)
        format("%.1f s", value)
      end

      def failures(view)
        failed = view.cells.select { |cell| cell.status == "failed" }
        return nil if failed.empty?

        items = failed.map do |cell|
          log = cell.log ? " <a href=\"#{h(cell.log)}\">whole log</a>" : ""
          "<h3 id=\"#{h(cell_id(view, cell))}\">#{h(cell.package)} <span class=\"muted\">(#{h(cell.source)})</span>#{log}</h3>\n" \
            "<pre class=\"error\">#{h(cell.first_error || 'no error line found in the log')}</pre>"
        end
        "<h3>Failed builds</h3>\n#{items.join("\n")}"
      end

      def cell_id(view, cell)
        "#{anchor(view.target)}-#{cell.source}"
      end

      def blocked(view)
        return nil if view.blockers.empty?

        items = view.blockers.map do |blocker|
          blocked = blocker.blocked.empty? ? "" : ": #{blocker.blocked.map { |name| h(name) }.join(', ')}"
          "<li><b>#{h(blocker.package)}</b> blocks #{blocker.blocked.size} " \
            "package#{'s' unless blocker.blocked.size == 1}#{blocked}</li>"
        end
        "<h3>Blocked</h3>\n<ol>\n#{items.join("\n")}\n</ol>"
      end

      # One table for the whole release: a row per package, a column per
      # target (decision, version, last build and its time in each cell); on
      # a narrow screen each row becomes a block and each cell names its
      # target.
      def matrix(page)
        return nil if page.targets.empty?

        rows = page.packages.map do |package|
          cells = page.targets.map do |view|
            found = view.cell(package)
            found ? "<td data-label=\"#{h(view.target)}\">#{matrix_cell(view, found)}</td>" : "<td></td>"
          end
          "<tr><td>#{h(package)}</td>#{cells.join}</tr>"
        end
        heads = page.targets.map { |view| "<th><a href=\"##{anchor(view.target)}\">#{h(view.target)}</a></th>" }
        "<h2 id=\"packages\">Packages</h2>\n<div class=\"scroll\"><table class=\"matrix\">\n<thead><tr><th>Package</th>" \
          "#{heads.join}</tr></thead>\n<tbody>\n#{rows.join("\n")}\n</tbody></table></div>"
      end

      def matrix_cell(view, cell)
        build = [status(view, cell), cell.duration && "<span class=\"muted\">#{seconds(cell.duration)}</span>"].compact
        build = build.reject(&:empty?)
        ["<div>#{decision(cell)}</div>", "<div><code>#{h(cell.version)}</code></div>",
         ("<div>#{build.join(' ')}</div>" unless build.empty?)].compact.join
      end

      DECISION_WORDS = { "build" => "built here", "published" => "published", "system" => "from the distribution",
                         "unavailable" => "unavailable" }.freeze

      def decision(cell)
        return "inherited from <b>#{h(cell.from)}</b>" if cell.decision == "inherit"

        h(DECISION_WORDS.fetch(cell.decision, cell.decision))
      end

      def status(view, cell)
        return "" unless cell.status

        badge = "<span class=\"badge #{h(cell.status.tr(' ', '-'))}\">#{h(cell.status)}</span>"
        case cell.status
        when "failed"
          "<a href=\"##{h(cell_id(view, cell))}\">#{badge}</a>"
        when "skipped"
          because = if cell.blocked_by&.any?
                      "because of #{cell.blocked_by.map { |source| h(package_of(view, source)) }.join(', ')}"
                    else
                      h(cell.reason)
                    end
          "#{badge} <span class=\"muted\">#{because}</span>"
        when "kept" then "#{badge} <span class=\"muted\">#{h(cell.reason)}</span>"
        else badge
        end
      end

      def package_of(view, source)
        view.cells.find { |cell| cell.source == source }&.package || source
      end

      def critical_path(view)
        return nil if view.critical_path.empty?

        chain = view.critical_path.map { |step| "#{h(package_of(view, step.source))} (#{seconds(step.duration)})" }
        "<h3>Critical path of the last build</h3>\n<p>#{chain.join(' → ')}: #{seconds(view.critical_seconds)} " \
          "<span class=\"muted\">(the chain of build-dependencies no number of jobs makes shorter)</span></p>"
      end

      # `relspec abi`'s verdicts in short: a count per verdict and the
      # libraries to review (docs/abi.md says what each verdict means).
      def abi(view)
        return nil unless view.abi

        title = "<h3>ABI against the ancestors' published dumps</h3>"
        return "#{title}\n<p class=\"muted\">not computed: #{h(view.abi.error)}</p>" if view.abi.error

        counts = view.abi.counts.reject { |_, count| count.zero? }.map { |name, count| "<span>#{count} #{h(name)}</span>" }
        items = view.abi.listed.map do |one|
          "<li><span class=\"badge #{h(one.verdict)}\">#{h(one.verdict)}</span> <code>#{h(one.library)}</code> " \
            "(#{h(one.package)}) <span class=\"muted\">against #{h(one.against)}</span></li>"
        end
        list = items.empty? ? "" : "\n<ul>\n#{items.join("\n")}\n</ul>"
        "#{title}\n<p class=\"totals\">#{counts.join(' ')}</p>#{list}"
      end

      def causes(view)
        explained = view.cells.select { |cell| cell.causes&.any? }
        return nil if explained.empty?

        items = explained.map do |cell|
          "<li>#{h(cell.package)}<pre>#{h(Plan::Cause.steps(cell.causes).join("\n"))}</pre></li>"
        end
        "<h3>Why they are built (or unavailable)</h3>\n<ul>\n#{items.join("\n")}\n</ul>"
      end

      def changes(view, page)
        return nil unless view.changes

        title = "<h3>Changes against #{h(page.ancestor)}</h3>"
        return "#{title}\n<p>none</p>" if view.changes.empty?

        rows = view.changes.map do |change|
          "<tr><td>#{h(change.package)}</td><td>#{h(change.change)}</td><td data-label=\"#{h(page.ancestor)}\">" \
            "#{h(change.old)}</td><td data-label=\"#{h(page.release)}\">#{h(change.new)}</td></tr>"
        end
        "#{title}\n<div class=\"scroll\"><table>\n<thead><tr><th>Package</th><th>Change</th>" \
          "<th>#{h(page.ancestor)}</th><th>#{h(page.release)}</th></tr></thead>\n<tbody>\n#{rows.join("\n")}\n</tbody></table></div>"
      end
    end
  end
end
