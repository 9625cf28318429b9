# frozen_string_literal: true

require "fileutils"
require_relative "../atomic_file"

module Relspec
  module Reprepro
    # The reprepro configuration of a repository relspec makes (a
    # release's, publish; a field mirror's): declarative, so by hand edits of
    # conf/ are overwritten. One distribution per codename, with every
    # architecture of the targets on it (plus `source` for a release's).
    class Config
      # reprepro retries a locked database this many times, 10 s apart
      # (`--waitforlock`): a second run waits for the first instead of
      # failing. relspec's own flock (Publish::RepositoryLock) normally makes
      # this a second line of defence, for reprepro runs started by hand.
      WAIT_FOR_LOCK = 30

      # +targets+: Target; +description+: a format of the codename
      # ("demo for %<codename>s"); +source+: the distributions hold sources;
      # +sign_with+: a gpg key id, or nil (unsigned).
      def initialize(label:, description:, targets:, source:, sign_with: nil)
        @label = label
        @description = description
        @targets = targets
        @source = source
        @sign_with = sign_with
      end

      def distributions
        @targets.group_by(&:codename).sort.map do |codename, targets|
          architectures = targets.map(&:arch).uniq.sort + (@source ? ["source"] : [])
          lines = ["Codename: #{codename}", "Suite: #{codename}", "Label: #{@label}",
                   "Architectures: #{architectures.join(' ')}", "Components: main",
                   "Description: #{format(@description, codename: codename)}"]
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

      # The files into +conf+ (made if missing); true when one changed.
      def write(conf)
        FileUtils.mkdir_p(conf)
        files.map { |name, text| AtomicFile.update(File.join(conf, name), text) }.any?
      end
    end
  end
end
