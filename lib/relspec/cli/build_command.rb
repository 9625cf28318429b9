# frozen_string_literal: true

require "json"
require_relative "../builder"
require_relative "../abi/interface_verdicts"

module Relspec
  module CLI
    # `relspec build SPEC`: builds what compile wrote, then prints a summary
    # table (or the results as JSON). Exits 1 when a package failed or was
    # skipped.
    class BuildCommand
      def initialize(path:, out:, backend:, jobs:, targets:, keep_going:, rebuild:, prepare:, format:, out_io:,
                     progress_io: nil, engine: "local", slurm: [], err_io: nil, rebuild_dependents: false)
        @path = path
        @options = { out: out, backend: backend, jobs: jobs, targets: targets, keep_going: keep_going,
                     rebuild: rebuild, prepare_only: prepare, engine: engine, notices: err_io,
                     rebuild_dependents: rebuild_dependents }
        @slurm = slurm
        @format = format
        @io = out_io
        @progress_io = progress_io
      end

      def call
        settings = Builder::Slurm::Settings.load(user_dir: config_home, project_dir: Dir.pwd, pairs: @slurm)
        reports = Builder.run(@path, **@options, slurm_settings: settings, listener: listener,
                                                 verdicts: Abi::InterfaceVerdicts.method(:of))
        @format == "json" ? @io.puts(JSON.pretty_generate(reports.map { |report| as_json(report) })) : print_text(reports)
        reports.any?(&:failed?) ? 1 : 0
      end

      private

      # A bar on stderr when it is a terminal; a line per package start and
      # end on stdout when it is not one, so that `relspec build > log`, CI
      # logs and `bin/demo > log` show where a build is (both when only
      # stdout goes to a file). None for --quiet or --format json (stdout is
      # then a tool's).
      def listener
        return nil unless @progress_io && @format == "text"

        listeners = []
        listeners << BuildProgress.new(@progress_io) if @progress_io.tty?
        listeners << BuildProgressLines.new(@io) unless @io.tty?
        listeners.size > 1 ? Listeners.new(listeners) : listeners.first
      end

      # Several progress listeners as one (Builder.run takes one).
      Listeners = Struct.new(:all) do
        %i[start building finished].each do |event|
          define_method(event) { |*args| all.each { |listener| listener.public_send(event, *args) } }
        end
      end

      # The user's configuration folder (XDG), nil without a home.
      def config_home
        base = ENV.fetch("XDG_CONFIG_HOME", "")
        base.empty? ? File.join(Dir.home, ".config") : base
      rescue ArgumentError
        nil
      end

      def print_text(reports)
        reports.each do |report|
          if @options[:prepare_only]
            @io.puts("#{report.target}: chroot #{report.prepared ? 'made' : 'ready'}")
            next
          end
          print_table(report)
        end
      end

      def print_table(report)
        rows = report.results.entries.map do |record|
          [record.source, record.version.to_s, record.status, record.duration ? format("%.1f s", record.duration) : "",
           (record.reason || cutoff_text(record) || interface_text(record.interface)).to_s.lines.first.to_s.strip]
        end
        kept = count(report, :kept)
        @io.puts("#{report.target}: #{count(report, :built)} built, #{"#{kept} kept, " if kept.positive?}" \
                 "#{report.reused} already built, " \
                 "#{count(report, :failed)} failed, #{count(report, :skipped)} skipped (#{report.dir})")
        return if rows.empty?

        widths = (0..3).map { |column| rows.map { |row| row[column].size }.max }
        rows.each do |row|
          @io.puts("  #{row.first(4).each_with_index.map { |cell, i| cell.ljust(widths[i]) }.join('  ')}  #{row[4]}".rstrip)
        end
      end

      # What the early cutoff decided for a candidate (docs/abi.md).
      def cutoff_text(record)
        cutoff = record.cutoff
        return nil unless cutoff

        cutoff.keep? ? "early cutoff: keeps #{cutoff.keeps}: #{cutoff.summary}" : "early cutoff: rebuilt: #{cutoff.reason}"
      end

      # The early cutoff's verdict of a build (docs/abi.md), in its row.
      def interface_text(interface)
        return nil unless interface

        text = "interface #{interface.verdict} from #{interface.against}"
        text += " (unpublished: the repository holds #{interface.held})" if interface.held
        interface.changes.empty? ? text : "#{text}: #{interface.changes.first}"
      end

      def count(report, status)
        report.outcomes.count { |outcome| outcome.status == status }
      end

      def as_json(report)
        { "target" => report.target.to_s, "folder" => report.dir,
          "packages" => (report.results&.entries || []).to_h { |record| [record.source, record.to_h] } }
      end
    end
  end
end
