# frozen_string_literal: true

module Relspec
  # Base of every error meant for a person: the CLI prints its message without
  # a backtrace and exits with +status_code+ (as Bundler's BundlerError).
  # Anything else that escapes is a bug in relspec (exit 70).
  class Error < StandardError
    def status_code
      1
    end
  end

  # Input was rejected; carries the diagnostics that say why.
  class InvalidInput < Error
    attr_reader :diagnostics

    def initialize(diagnostics)
      @diagnostics = diagnostics.sort_by(&:sort_key).freeze
      super(@diagnostics.join("\n"))
    end
  end

  # A command-line option has a value relspec cannot use.
  class InvalidOption < Error; end

  # releases/<r>/lock.yml cannot be read; it is never overwritten then.
  class LockError < InvalidInput; end

  # A repository (ancestor, own, distribution archive) cannot be read or
  # cannot be trusted.
  class RepositoryError < Error; end

  # An external tool (dpkg-source, tar, gzip, sbuild, reprepro, gpg) failed.
  class ToolError < Error; end

  # A build or a publication failed (the builder and the publisher).
  class BuildError < ToolError; end
  class PublishError < ToolError; end
end
