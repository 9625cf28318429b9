# frozen_string_literal: true

require "dry/schema"

module Relspec
  module ReleaseSpec
    # The shape of a release spec, format version 1 (docs/spec-reference.md).
    #
    # Each schema describes one flat mapping. Mappings whose keys are chosen by
    # the user (pins, gems, targets, external, distributions) are checked entry
    # by entry with the entry schemas, because a schema with validate_keys would
    # reject every package name as an unknown key.
    module Schema
      RELEASE = Dry::Schema.JSON do
        config.validate_keys = true
        required(:release).filled(:string)
        optional(:parent)
        optional(:description).filled(:string)
        optional(:workspace).filled(:string)
        optional(:select).array(:str?)
        optional(:blacklist).array { str? | hash? }
        optional(:leave_out).array(:hash?)
        optional(:pins).value(:hash)
        optional(:gems).value(:hash)
        optional(:gem_source).filled(:string)
        optional(:targets).value(:hash)
        optional(:repository).value(:hash)
        optional(:install_prefix).filled(:string)
        optional(:separate_prefixes).value(:bool)
        optional(:package_prefix).filled(:string)
        optional(:maintainer).filled(:string)
        optional(:external).value(:hash)
        optional(:distributions).value(:hash)
        optional(:early_cutoff).value(:hash)
      end

      # Mappings checked by their own schemas (entry by entry where users choose the keys).
      CHECKED_SEPARATELY = %w[pins gems targets external distributions repository early_cutoff].freeze

      # The early cutoff (docs/abi.md), on unless `enabled: false`, which
      # needs a reason (Rules::EarlyCutoff).
      EARLY_CUTOFF = Dry::Schema.JSON do
        config.validate_keys = true
        required(:enabled).value(:bool)
        optional(:reason).filled(:string)
      end

      BLACKLIST_ENTRY = Dry::Schema.JSON do
        config.validate_keys = true
        required(:match).filled(:string)
        optional(:reason).filled(:string)
      end

      LEAVE_OUT_ENTRY = Dry::Schema.JSON do
        config.validate_keys = true
        required(:match).filled(:string)
        required(:reason).filled(:string)
        optional(:targets).array(:str?)
      end

      PIN = Dry::Schema.JSON do
        config.validate_keys = true
        optional(:commit).filled(:string)
        optional(:tag).filled(:string)
        optional(:branch).filled(:string)
      end

      REPOSITORY = Dry::Schema.JSON do
        config.validate_keys = true
        optional(:path).filled(:string)
        optional(:url).filled(:string)
        optional(:keyring).filled(:string)
        optional(:trusted).value(:bool)
      end

      # The release's own repository: also how `relspec publish` signs it
      # (a gpg key id or fingerprint for reprepro's SignWith) and whether it
      # carries the -dbgsym packages the build made (default: no).
      OWN_REPOSITORY = Dry::Schema.JSON(parent: REPOSITORY) do
        config.validate_keys = true
        optional(:sign_with).filled(:string)
        optional(:debug_symbols).value(:bool)
      end

      # An external release is a repository plus what it tells its descendants.
      EXTERNAL = Dry::Schema.JSON(parent: REPOSITORY) do
        config.validate_keys = true
        optional(:package_prefix).filled(:string)
        optional(:install_prefix).filled(:string)
        optional(:separate_prefixes).value(:bool)
        optional(:targets).value(:hash)
      end

      # type and labels are required for codenames relspec does not know
      # (Rules::Settings); archive is the distribution's own apt archive.
      DISTRIBUTION = Dry::Schema.JSON do
        config.validate_keys = true
        optional(:type).filled(:string, included_in?: %w[ubuntu debian])
        optional(:labels).filled(:array).each(:str?)
        optional(:archive).value(:hash)
        optional(:debhelper_compat).filled(:integer, gteq?: 9, lteq?: 14)
      end

      # Where the distribution's packages can be read (to prefer its ruby-*
      # packages over packaging gems): a repository plus its components.
      # host: true reads this machine's apt lists instead (Apt::HostLists).
      ARCHIVE = Dry::Schema.JSON(parent: REPOSITORY) do
        config.validate_keys = true
        optional(:components).filled(:array).each(:str?)
        optional(:host).value(:bool)
      end

      def self.keys(schema)
        schema.key_map.map(&:name)
      end
    end
  end
end
