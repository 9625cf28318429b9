# frozen_string_literal: true

require "yaml"
require_relative "../trust"
require_relative "refusal"

module RelspecPackageSet
  # The env.yml of the installed active packages ({VAR => {type:, values:,
  # priority:}}, symbol keys), for the workspace's environment; negative
  # priorities last. Only a file below Trust::PREFIX, of a release of the
  # lineage, changing the variables Trust allows, to paths below the
  # prefix: read and checked as a whole before any of it is applied. A
  # package not installed yet has none: the next autoproj run reads it.
  class Environment
    def self.read(lineage, debs)
      prefix = Relspec::Osdeps::Trust::PREFIX
      paths = lineage.product(debs).map { |release, deb| File.join(prefix, release, deb, "env.yml") }
      new(paths.select { |path| File.file?(path) }.sort.flat_map { |path| operations(path) })
    end

    def self.operations(path)
      problem = Relspec::Osdeps::Trust.environment_file(path)
      RelspecPackageSet.refuse("#{path}: #{problem}") if problem
      data = YAML.safe_load(File.read(path), permitted_classes: [Symbol]) || {}
      RelspecPackageSet.refuse("#{path}: is not a mapping of variables") unless data.is_a?(Hash)
      data.each do |name, entry|
        problem = Relspec::Osdeps::Trust.environment(name, entry)
        RelspecPackageSet.refuse("#{path}: #{problem}") if problem
      end
      first, last = data.partition { |_, entry| entry[:priority].to_i >= 0 }
      (first + last).flat_map do |name, entry|
        Array(entry[:values]).map { |value| [entry[:type], name, value] }
      end
    rescue Psych::Exception => e
      RelspecPackageSet.refuse("#{path}: is not plain YAML (#{e.message})")
    end

    def initialize(operations)
      @operations = operations
    end

    def apply(env)
      @operations.each do |type, name, value|
        case type
        when :add_path then env.add_path(name, value)
        when :add then env.add(name, value)
        when :set then env.set(name, value)
        end
      end
    end
  end
end
