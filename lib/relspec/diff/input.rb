# frozen_string_literal: true

require_relative "lock_view"
require_relative "../error"
require_relative "../yaml/located_document"

module Relspec
  module Diff
    # What `relspec diff OLD NEW` accepts, as Snapshots: a lock file, a
    # release folder (releases/<r>/ holding lock.yml), or a spec file, which
    # is planned first. The spec file's own data is attached when known, so
    # that spec-level changes can be shown.
    module Input
      LOCK_FILE = "lock.yml"
      # How every lock LockGenerator writes begins.
      LOCK_MARK = /\A---\n#{Plan::Lock::FORMAT_KEY}:/

      module_function

      # +planner+: (spec path) => Plan::Lock, for spec inputs.
      def snapshot(argument, planner:)
        path = argument.to_s
        if File.directory?(path)
          release_folder(path)
        elsif File.file?(path)
          file(path, planner)
        else
          raise Error, "#{path}: no such lock file, release folder or spec"
        end
      end

      def release_folder(path)
        lock = File.join(path, LOCK_FILE)
        raise Error, "#{path} is not a release folder: it has no #{LOCK_FILE}" unless File.exist?(lock)

        # No spec is attached: which spec the lock was planned from is not
        # known (the one in specs/ may be the changed one).
        LockView.parse(text_of(lock), source: lock)
      end

      def file(path, planner)
        text = text_of(path)
        raise Error, "#{path} is empty: neither a relspec lock nor a release spec" if text.strip.empty?

        # A lock is read once, by the lock parser (a lock of 400 packages
        # costs a tenth of a second per YAML read).
        return LockView.parse(text, source: path) if text.match?(LOCK_MARK)

        data = spec_data(text, path)
        raise Error, "#{path} is neither a relspec lock nor a release spec" unless data.key?("release")

        LockView.snapshot(planner.call(path), source: path).with_spec(data, spec_dir: File.dirname(path))
      end

      # A file's text, read as every YAML input is (regular file, size limit,
      # UTF-8 or UTF-16): anything else is an InvalidInput naming the file.
      def text_of(path)
        text, refusal = Yaml::LocatedDocument.read_text(path)
        raise InvalidInput, [refusal] if refusal

        text
      end

      # The spec (or lock) file's data; {} for anything that is not a mapping.
      def spec_data(text, source)
        document = Yaml::LocatedDocument.parse(text, file: source)
        raise InvalidInput, document.diagnostics unless document.ok?

        document.data.is_a?(Hash) ? document.data : {}
      end
    end
  end
end
