# frozen_string_literal: true

module Relspec
  module Publish
    # The reprepro configuration of a release's repository, generated from
    # the spec (declarative: the spec says what the repository is, by hand
    # edits of conf/ are overwritten). One distribution per codename, with
    # every architecture of the release's targets on it plus `source`.
    class RepositoryConfig
      # reprepro retries a locked database this many times, 10 s apart
      # (`--waitforlock`): a second publisher waits for the first instead
      # of failing. relspec's own flock (RepositoryLock) normally makes this
      # a second line of defence, for reprepro runs started by hand.
      WAIT_FOR_LOCK = 30

      # +targets+: Target; +sign_with+: a gpg key id, or nil (unsigned).
      def initialize(release:, targets:, sign_with: nil)
        @release = release
        @targets = targets
        @sign_with = sign_with
      end

      def distributions
        @targets.group_by(&:codename).sort.map do |codename, targets|
          lines = ["Codename: #{codename}", "Suite: #{codename}", "Label: #{@release}",
                   "Architectures: #{(targets.map(&:arch).uniq.sort + ['source']).join(' ')}",
                   "Components: main", "Description: #{@release} for #{codename}"]
          lines << "SignWith: #{@sign_with}" if @sign_with
          "#{lines.join("\n")}\n"
        end.join("\n")
      end

      def options
        "waitforlock #{WAIT_FOR_LOCK}\n"
      end

      # conf/<name> => content
      def files
        { "distributions" => distributions, "options" => options }
      end
    end
  end
end
