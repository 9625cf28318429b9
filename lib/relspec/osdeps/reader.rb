# frozen_string_literal: true

require "yaml"
require_relative "trust"

module Relspec
  module Osdeps
    # The one reader of the osdeps files a release publishes and the package
    # set ships (docs/osdeps.md): releases.yml ({release => {depends_on:
    # parent}}, beside its `default` entry) and <release>-<arch>.yml
    # ({autoproj package => {OS types => {labels => Debian name}}}).
    # `osdeps select`, `osdeps package-set`, mirror and the package set's
    # init.rb (in users' workspaces, without relspec) read them through it,
    # so all refuse the same things: every release name is checked (Trust),
    # and every Debian name a system resolves to (it reaches apt, as root).
    # The published Rock files hold entries of other shapes (gems, lists for
    # old systems): a reader checks what it uses; relspec's own writer checks
    # every entry (osdeps_problems) before it ships a file.
    # Plain Ruby, requiring only files the package set ships. As in
    # trust.rb, a reading is a value or the reason it is none (Reading),
    # which each caller words as its own error.
    module Reader
      Reading = Struct.new(:value, :reason) do
        def ok?
          reason.nil?
        end
      end

      module_function

      # +text+ as plain data (no aliases, no objects); +empty+ for an empty file.
      def yaml(text, empty: nil)
        data = YAML.safe_load(text, aliases: false)
        value(data.nil? ? empty : data)
      rescue Psych::Exception => e
        reason("is not plain YAML (#{e.message.sub(/\A\(.*?\): /, '')})")
      end

      # releases.yml's data → {release => its parent, or nil}, `default` left out.
      def releases(data)
        return reason("is not a mapping of releases") unless data.is_a?(Hash)

        index = {}
        data.each do |name, entry|
          next if name == "default"

          parent = entry.is_a?(Hash) ? entry["depends_on"] : nil
          problem = Trust.release_name(name) || (entry.nil? || entry.is_a?(Hash) ? nil : "is not a mapping") ||
                    (parent && Trust.release_name(parent))
          return reason("#{name.inspect}: #{problem}") if problem

          index[name] = parent
        end
        value(index.freeze)
      end

      # The release's ancestors, root first, then +release+ (a key of
      # +index+, Reader.releases): a cycle or a parent the index does not
      # hold is the reason.
      def lineage(index, release)
        chain = [release]
        while (parent = index[chain.first])
          return reason("depends_on cycle through #{parent}") if chain.include?(parent)
          return reason("#{chain.first} depends on #{parent}, which it does not hold") unless index.key?(parent)

          chain.unshift(parent)
        end
        value(chain.freeze)
      end

      # Every problem of an osdeps file's data, one per package, by package.
      def osdeps_problems(data)
        return ["is not a mapping of packages"] unless data.is_a?(Hash)

        data.sort_by { |package, _| package.to_s }.filter_map do |package, entry|
          problem = entry_problem(entry)
          "#{package}: #{problem}" if problem
        end
      end

      def entry_problem(entry)
        return "is not a mapping of OS types" unless entry.is_a?(Hash) && entry.values.all?(Hash)

        entry.values.flat_map(&:values).filter_map { |deb| Trust.debian_name(deb) }.first
      end

      # {package => Debian name} of osdeps +data+ for +os+ (an
      # OperatingSystem: autoproj's names and versions of the system), each
      # name checked; the reason names the first package (by name) whose
      # entry gives no Debian name. +lists+: a list of Debian names is one
      # too (autoproj's form for several packages, in the published Rock
      # files `osdeps select` reads; relspec never writes one).
      def resolve(data, os, lists: false)
        return reason("is not a mapping of packages") unless data.is_a?(Hash)

        mapping = data.sort_by { |package, _| package.to_s }.filter_map do |package, entry|
          next unless (deb = os.resolve(entry))

          names = lists && deb.is_a?(Array) && !deb.empty? ? deb : [deb]
          problem = names.filter_map { |name| Trust.debian_name(name) }.first
          return reason("#{package}: #{problem}") if problem

          [package, deb]
        end
        value(mapping.to_h.freeze)
      end

      def value(value)
        Reading.new(value, nil).freeze
      end

      def reason(reason)
        Reading.new(nil, reason).freeze
      end
      private_class_method :entry_problem, :value, :reason
    end
  end
end
