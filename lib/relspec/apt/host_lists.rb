# frozen_string_literal: true

require "open3"
require "English"
require_relative "repository"

module Relspec
  module Apt
    # The apt lists of the machine relspec runs on (/var/lib/apt/lists after
    # `apt-get update`), read like a Repository: apt itself says which index
    # files it has (`apt-get indextargets`) and decompresses them
    # (`apt-helper cat-file`, whatever compression apt chose to keep them in,
    # e.g. lz4). apt verified the InRelease signatures when it downloaded
    # them; the index text is verified here against the SHA256 that the
    # stored InRelease gives for the uncompressed index.
    class HostLists
      APT_HELPER = "/usr/lib/apt/apt-helper"
      FORMAT = "$(RELEASE)\t$(COMPONENT)\t$(ARCHITECTURE)\t$(METAKEY)\t$(FILENAME)\t$(REPO_URI)"

      # One downloaded Packages index; +repo_uri+: the archive's base URL,
      # where the index's Filename fields are found.
      Target = Struct.new(:suite, :component, :arch, :meta_key, :filename, :repo_uri)

      def url
        "this machine's apt lists"
      end

      # The architectures whose indices apt fetched for +arch+ in +codename+:
      # binary-all only where apt keeps one (it skips it where the archive
      # says No-Support-for-Architecture-all: Packages), as the stored
      # InRelease allows it.
      def index_architectures(codename, arch, component: "main")
        all = targets.find { |target| target.suite == codename && target.arch == "all" && target.component == component }
        all && release_of(all).package_architectures(arch, component: component).include?("all") ? [arch, "all"] : [arch]
      end

      def packages(codename, arch, component: "main")
        PackageIndex.parse(packages_text(codename, arch, component: component))
      rescue Deb822::ParseError, ArgumentError, PackageIndex::Invalid => e
        raise Repository::Error, "#{url} (#{codename}/#{component}/binary-#{arch}): malformed index: #{e.message}"
      end

      def packages_text(codename, arch, component: "main")
        verified_text(target_for(codename, arch, component))
      end

      def index_digest(codename, arch, component: "main")
        target = target_for(codename, arch, component)
        checksum = release_of(target).checksum(target.meta_key)
        raise Repository::Error, "#{target.filename}: its InRelease lists no #{target.meta_key}" unless checksum

        checksum.sha256
      end

      # The indices of +codename+ and of its point-release suites
      # (codename-updates, codename-security) that apt has for +arch+ (and
      # its binary-all where apt reads one: #index_architectures), each
      # as [Target, verified text]: what a machine of that distribution
      # installs from. Only a distribution's archive says who made it
      # (Origin: Debian, Ubuntu): a repository of releases served under the
      # same codename (relspec's, reprepro's by default) has no Origin and
      # is not the distribution; nor is a source apt never fetched.
      def suite_indices(codename, arch, component: "main")
        suites = [codename, "#{codename}-updates", "#{codename}-security"]
        found = targets.select do |target|
          suites.include?(target.suite) && index_architectures(target.suite, arch, component: component).include?(target.arch) &&
            target.component == component && distribution?(target)
        end
        target_for(codename, arch, component) if found.none? { |target| target.arch == arch } # says what is missing
        found.map { |target| [target, verified_text(target)] }
      end

      private

      def distribution?(target)
        !release_of(target).origin.to_s.strip.empty?
      rescue Repository::Error
        false
      end

      def verified_text(target)
        text = read_index(target.filename)
        checksum = release_of(target).checksum(target.meta_key)
        raise Repository::Error, "#{target.filename}: its InRelease lists no #{target.meta_key}" unless checksum
        unless text.bytesize == checksum.size && Digest::SHA256.hexdigest(text) == checksum.sha256
          raise Repository::Error, "#{target.filename} does not match the SHA256 of its InRelease: run apt-get update"
        end

        text
      end

      def target_for(codename, arch, component)
        found = targets.find { |t| t.suite == codename && t.arch == arch && t.component == component }
        return found if found

        raise Repository::Missing, "#{url} have no #{codename} #{component} #{arch} Packages index " \
                                   "(configure it in /etc/apt/sources.list.d and run apt-get update)"
      end

      def targets
        @targets ||= run("apt-get", "indextargets", "--format", FORMAT, "Identifier: Packages").lines.filter_map do |line|
          suite, component, arch, meta_key, filename, repo_uri = line.chomp.split("\t")
          next unless filename && File.file?(filename)

          Target.new(suite, component, arch, meta_key, filename, repo_uri.to_s.chomp("/")).freeze
        end
      end

      # The InRelease stored beside the index: same file name up to the
      # meta key, which apt writes with "_" for "/".
      def release_of(target)
        @releases ||= {}
        base = target.filename.sub(/_#{Regexp.escape(target.meta_key.tr('/', '_'))}(\.[a-z0-9]+)?\z/, "_")
        @releases[base] ||= begin
          bytes = File.binread("#{base}InRelease")
          ReleaseFile.parse(Signature.unarmor(bytes).force_encoding(Encoding::UTF_8), raw: bytes)
        rescue SystemCallError => e
          raise Repository::Error, "#{url}: cannot read the InRelease of #{target.filename}: #{e.message}"
        end
      end

      # A pipe read straight into one String (capture3's threads cost twice
      # as much on a 50 MB index).
      def read_index(filename)
        text = IO.popen([APT_HELPER, "cat-file", filename], "rb", err: File::NULL, &:read)
        raise Repository::Error, "#{url}: apt-helper cannot read #{filename}" unless $CHILD_STATUS.success?

        text
      rescue SystemCallError => e
        raise Repository::Error, "#{url}: cannot run #{APT_HELPER}: #{e.message}"
      end

      def run(*command)
        out, err, status = Open3.capture3(*command, binmode: true)
        raise Repository::Error, "#{url}: #{command.first(2).join(' ')} failed: #{err.strip}" unless status.success?

        out
      rescue SystemCallError => e
        raise Repository::Error, "#{url}: cannot run #{command.first}: #{e.message}"
      end
    end
  end
end
