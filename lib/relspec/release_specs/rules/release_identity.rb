# frozen_string_literal: true

require_relative "../names"
require_relative "../../diagnostic"

module Relspec
  module ReleaseSpec
    module Rules
      # The release name is what every Debian package and path of the release
      # is built from, and the file name is how parents are found.
      module ReleaseIdentity
        def self.call(file)
          release = file.usable("release")
          return [] unless release.is_a?(String)

          location = file.location(["release"])
          unless Names.release?(release)
            return [Diagnostic.error("release-name", "invalid release name #{release.inspect}", location: location,
                                                                                                hint: Names::RELEASE_HINT)]
          end
          return [] if release == file.file_release

          [Diagnostic.error("file-name", "release #{release.inspect} is declared in a file named " \
                                         "#{File.basename(file.path).inspect}",
                            location: location,
                            hint: "rename the file to #{release}.yml or set `release: #{file.file_release}`")]
        end
      end
    end
  end
end
