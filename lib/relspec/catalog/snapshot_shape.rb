# frozen_string_literal: true

require_relative "vcs"
require_relative "os_dependencies"
require_relative "../diagnostic"

module Relspec
  class Catalog
    # The shape a catalog snapshot must have before it becomes a Catalog:
    # each field's type, checked node by node so that a hand-edited or
    # damaged snapshot is refused at the place that is wrong (file:line)
    # rather than failing somewhere inside the objects built from it.
    module SnapshotShape
      TEXT = ->(value) { value.is_a?(String) }
      OPTIONAL_TEXT = ->(value) { value.nil? || value.is_a?(String) }
      SCALAR = ->(value) { value.nil? || value.is_a?(String) || value.is_a?(Numeric) || value == true || value == false }
      BOOLEAN = ->(value) { [true, false].include?(value) }

      PACKAGE_TEXT = %w[package_set build_type commit_time version summary description license maintainer
                        source_dir extension_task].freeze

      module_function

      # Whether +data+ (from relspec's own catalog cache, which has no
      # document to locate problems in) has the shape.
      def valid?(data)
        data.is_a?(Hash) && problems(data, nil).empty?
      end

      # Diagnostics for what is wrong in +data+ (a Hash), located in
      # +document+ when there is one.
      def problems(data, document)
        found = []
        check = lambda do |path, ok, wanted|
          found << Diagnostic.error("catalog-format", "malformed catalog snapshot: #{path.join('.')} must be #{wanted}",
                                    location: document&.location(path),
                                    hint: "regenerate it with `relspec catalog export`")
          ok
        end
        check_top(data, check)
        found.uniq(&:message)
      end

      def check_top(data, check)
        %w[codenames layout excluded ignored weak_metapackages].each { |key| list_of_text(data, [key], check) }
        reasons = data.fetch("exclusion_reasons", {})
        if hash?(reasons, ["exclusion_reasons"], check)
          reasons.each { |name, reason| check.call(["exclusion_reasons", name], false, "text") unless TEXT.call(reason) }
        end
        metapackages = data.fetch("metapackages", {})
        if hash?(metapackages, ["metapackages"], check)
          metapackages.each_key { |name| list_of_text(metapackages, [name], check, prefix: ["metapackages"]) }
        end
        packages = data.fetch("packages", {})
        return unless hash?(packages, ["packages"], check)

        packages.each do |name, entry|
          path = ["packages", name]
          check_package(entry, path, check) if hash?(entry, path, check)
        end
      end

      def check_package(entry, path, check)
        PACKAGE_TEXT.each do |key|
          check.call(path + [key], false, "text") unless OPTIONAL_TEXT.call(entry[key])
        end
        check.call(path + ["checked_out"], false, "true or false") if entry.key?("checked_out") && !BOOLEAN.call(entry["checked_out"])
        %w[dependencies optional_dependencies copyright orogen_arguments].each { |key| list_of_text(entry, [key], check, prefix: path) }
        check_vcs(entry.fetch("vcs", {}), path + ["vcs"], check)
        check_os_dependencies(entry.fetch("os_dependencies", {}), path + ["os_dependencies"], check)
        check_environment(entry.fetch("environment", []), path + ["environment"], check)
        check_patches(entry.fetch("patches", []), path + ["patches"], check)
        defines = entry.fetch("defines", {})
        return unless hash?(defines, path + ["defines"], check)

        defines.each { |key, value| check.call(path + ["defines", key], false, "a scalar") unless SCALAR.call(value) }
      end

      def check_environment(operations, path, check)
        return check.call(path, false, "a list") unless operations.is_a?(Array)

        operations.each_with_index do |op, index|
          next if op.is_a?(Hash) && %w[set add add_path].include?(op["type"]) && TEXT.call(op["name"]) &&
                  op["values"].is_a?(Array) && op["values"].all?(TEXT)

          check.call(path + [index], false, "{type: set|add|add_path, name: text, values: [text]}")
        end
      end

      def check_patches(patches, path, check)
        return check.call(path, false, "a list") unless patches.is_a?(Array)

        patches.each_with_index do |patch, index|
          next if patch.is_a?(Hash) && TEXT.call(patch["path"]) && TEXT.call(patch["content"]) &&
                  patch.fetch("level", 0).is_a?(Integer) && patch.fetch("level", 0) >= 0

          check.call(path + [index], false, "{path: text, level: a number from 0, content: text}")
        end
      end

      def check_vcs(vcs, path, check)
        return unless hash?(vcs, path, check)

        vcs.each do |key, value|
          if !Vcs.members.map(&:to_s).include?(key)
            check.call(path + [key], false, "one of #{Vcs.members.join(', ')}")
          elsif !OPTIONAL_TEXT.call(value)
            check.call(path + [key], false, "text")
          end
        end
      end

      def check_os_dependencies(by_codename, path, check)
        return unless hash?(by_codename, path, check)

        by_codename.each do |codename, lists|
          next unless hash?(lists, path + [codename], check)

          lists.each_key do |field|
            if OsDependencies::FIELDS.include?(field)
              list_of_text(lists, [field], check, prefix: path + [codename])
            else
              check.call(path + [codename, field], false, "one of #{OsDependencies::FIELDS.join(', ')}")
            end
          end
        end
      end

      def hash?(value, path, check)
        value.is_a?(Hash) || check.call(path, false, "a mapping")
      end

      def list_of_text(container, key_path, check, prefix: [])
        value = container.fetch(key_path.last, [])
        path = prefix + key_path
        return check.call(path, false, "a list") unless value.is_a?(Array)

        value.each_with_index { |item, index| check.call(path + [index], false, "text") unless TEXT.call(item) }
      end
    end
  end
end
