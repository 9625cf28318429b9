# frozen_string_literal: true

require "yaml"
require_relative "../../error"

module Relspec
  module Builder
    module Slurm
      # What belongs to the cluster, not to the release: where and how jobs
      # run. Read from the user's file ($XDG_CONFIG_HOME/relspec/slurm.yml),
      # then the project's (.relspec/slurm.yml in the folder relspec runs
      # in), then `--slurm KEY=VALUE` options, each overriding the one
      # before. docs/scale-out.md lists the keys.
      class Settings
        KEYS = {
          "partition" => :string, # sbatch --partition
          "account" => :string, # sbatch --account
          "time_limit" => :string, # sbatch --time, e.g. 2:00:00
          "memory" => :string, # sbatch --mem, e.g. 4G
          "cpus_per_build" => :integer, # sbatch --cpus-per-task
          "shared_folder" => :string, # chroot tarballs, on a filesystem every node sees
          "poll_interval" => :number, # seconds between two squeue calls
          "features" => :hash # architecture => node feature ("" = no constraint)
        }.freeze
        FILE = "slurm.yml"

        attr_reader :values

        # +user_dir+: the user's config folder; +project_dir+: where relspec
        # runs; +pairs+: "KEY=VALUE" strings from the command line.
        def self.load(user_dir:, project_dir:, pairs: [])
          values = {}
          [user_dir && File.join(user_dir, "relspec", FILE), project_dir && File.join(project_dir, ".relspec", FILE)]
            .compact.select { |path| File.file?(path) }.each { |path| merge(values, from_file(path)) }
          merge(values, from_pairs(pairs))
          new(values)
        end

        def self.from_file(path)
          text = File.read(path)
          data = YAML.safe_load(text) || {}
          raise InvalidOption, "#{path}:1: error[slurm-settings]: not a mapping of settings" unless data.is_a?(Hash)

          data.each { |key, value| check(key.to_s, value, "#{path}:#{line_of(text, key)}") }
          data.transform_keys(&:to_s)
        rescue Psych::SyntaxError => e
          raise InvalidOption, "#{path}:#{e.line}: error[slurm-settings]: cannot be read (#{e.problem})"
        end

        def self.from_pairs(pairs)
          pairs.each_with_object({}) do |pair, values|
            key, value = pair.split("=", 2)
            raise InvalidOption, "--slurm #{pair}: error[slurm-settings]: not KEY=VALUE" if value.nil?

            if key.start_with?("features.")
              (values["features"] ||= {})[key.delete_prefix("features.")] = value
              next
            end
            value = convert(key, value, "--slurm #{pair}")
            check(key, value, "--slurm #{pair}")
            values[key] = value
          end
        end

        def self.convert(key, value, where)
          case KEYS[key]
          when :integer then Integer(value, 10)
          when :number then Float(value)
          else value
          end
        rescue ArgumentError
          raise InvalidOption, "#{where}: error[slurm-settings]: #{key} must be a number"
        end

        def self.check(key, value, where)
          type = KEYS[key] or
            raise InvalidOption, "#{where}: error[slurm-settings]: unknown setting #{key.inspect} " \
                                 "(known: #{KEYS.keys.join(', ')})"
          valid = case type
                  when :integer then value.is_a?(Integer) && value.positive?
                  when :number then value.is_a?(Numeric) && value.positive?
                  when :hash then value.is_a?(Hash) && value.all? { |_, feature| feature.is_a?(String) }
                  else value.is_a?(String) && !value.empty?
                  end
          return if valid

          raise InvalidOption, "#{where}: error[slurm-settings]: #{key} must be #{description(type)}"
        end

        def self.description(type)
          { integer: "a positive whole number", number: "a positive number",
            hash: "a mapping of architecture to feature name" }.fetch(type, "a non-empty string")
        end

        def self.line_of(text, key)
          (text.lines.index { |line| line.match?(/\A#{Regexp.escape(key.to_s)}\s*:/) } || 0) + 1
        end

        def self.merge(values, more)
          more.each do |key, value|
            values[key] = key == "features" ? (values["features"] || {}).merge(value) : value
          end
        end

        def initialize(values)
          @values = values.freeze
          freeze
        end

        def [](key)
          @values[key]
        end

        # The node feature a job of +arch+ needs (default: the
        # architecture's name); nil when the settings say "" (any node).
        def feature(arch)
          feature = (@values["features"] || {}).fetch(arch, arch)
          feature.empty? ? nil : feature
        end

        def poll_interval
          @values.fetch("poll_interval", 5)
        end

        # sbatch options every job of a run gets.
        def sbatch_options
          { "partition" => "--partition", "account" => "--account", "time_limit" => "--time", "memory" => "--mem",
            "cpus_per_build" => "--cpus-per-task" }.filter_map { |key, option| @values[key] && "#{option}=#{@values[key]}" }
        end
      end
    end
  end
end
