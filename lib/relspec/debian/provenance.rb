# frozen_string_literal: true

require_relative "template"
require_relative "license_name"

module Relspec
  module Debian
    # debian/changelog and debian/copyright of one package, from its
    # BuildInput: where the upstream code comes from (repository, commit,
    # its time) and under which license, by whom.
    class Provenance
      Context = Struct.new(:source, :version, :codename, :release, :package_name, :vcs_url, :vcs_ref, :build_type,
                           :commit, :maintainer, :date, :public_source, :copyright_holders, :license_name, :license,
                           :common_license, keyword_init: true)
      METHODS = Template.compile(Context, %w[changelog.erb copyright.erb])

      # A repository inside the workspace ($AUTOPROJ_ROOT/…, a folder of
      # the maintainer's machine) is no public source: it is named relative
      # to the workspace, and debian/copyright leaves Source: out.
      WORKSPACE_URL = %r{\A\$AUTOPROJ_ROOT/}

      def initialize(input)
        @in = input
      end

      # +version+: the text of the package's version (or the placeholder
      # of the digest's rendering).
      def changelog(version)
        package = @in.package
        Template.render(Context, METHODS, "changelog.erb",
                        source: @in.deb_name, version: version, codename: @in.codename, release: @in.release,
                        package_name: package.name, vcs_url: shown_url(package.vcs.url.to_s), vcs_ref: vcs_ref(package.vcs),
                        build_type: package.build_type, commit: package.vcs.commit.to_s, maintainer: @in.maintainer,
                        date: changelog_date)
      end

      def copyright
        package = @in.package
        license = license_text
        Template.render(Context, METHODS, "copyright.erb",
                        package_name: package.name, public_source: public_url(package.vcs.url.to_s),
                        copyright_holders: copyright_holders, license: license, license_name: LicenseName.of(license),
                        common_license: LicenseName.common_license_file(LicenseName.of(license)))
      end

      private

      # The upstream holders (manifest.xml's <copyright>, authors or
      # maintainers; a gem's authors), never the release's maintainer.
      def copyright_holders
        package = @in.package
        holders = package.copyright.empty? ? package.maintainer.to_s.split(", ") : package.copyright
        holders.empty? ? ["the authors of #{package.name}"] : holders
      end

      def license_text
        text = @in.package.license.to_s.strip.gsub(/\s+/, " ")
        text.empty? ? "unknown" : text
      end

      def shown_url(url)
        url.match?(WORKSPACE_URL) ? "the autoproj workspace's #{url.sub(WORKSPACE_URL, '')}" : url
      end

      def public_url(url)
        url.match?(%r{\A(https?|git|ssh)://|\A[\w.-]+@[\w.-]+:}) ? url : nil
      end

      def vcs_ref(vcs)
        if vcs.tag then "tag #{vcs.tag}, "
        elsif vcs.branch then "branch #{vcs.branch}, "
        else ""
        end
      end

      # RFC 2822 date of the commit (never the time of the run).
      def changelog_date
        time = @in.package.commit_time
        Time.utc(*time.scan(/\d+/).map(&:to_i)).strftime("%a, %d %b %Y %H:%M:%S +0000")
      end
    end
  end
end
