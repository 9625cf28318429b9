# frozen_string_literal: true

require_relative "operating_system"
require_relative "release_data"
require_relative "blacklist_file"
require_relative "index_sources"
require_relative "selection"
require_relative "files"
require_relative "trust"

module Relspec
  module Osdeps
    # `relspec osdeps select`: the user-side selection. Everything is read
    # and computed before anything is written, and both files are written
    # with rename, so a bad blacklist leaves the previous files untouched.
    module UserSelection
      # +selection+: the Osdeps::Selection written; +path+: rock-osdeps.osdeps.
      Result = Struct.new(:selection, :path, keyword_init: true)

      module_function

      # +data+: the folder of releases.yml and the osdeps files; +os+:
      # autoproj's "names:versions"; +index+: Packages files or repository
      # URLs for reverse dependencies (read with +timeout+, --timeout);
      # +output+: where the files go.
      # Before anything is written, +differs+ is called with each blacklist
      # entry the rock-osdeps package set reads differently (and the note
      # saying how), then +unmatched+ with each entry that matches no package.
      def call(release:, arch:, os:, data:, blacklist:, index:, trusted:, keyring:, output:, timeout: 10,
               unmatched: nil, differs: nil)
        check_names(release, arch, os)
        os = OperatingSystem.parse(os)
        mapping = ReleaseData.new(data).resolved(release, arch, os)
        entries = blacklist ? BlacklistFile.load(blacklist) : []
        indices = IndexSources.load(index, codename: codename(os), arch: arch, trusted: trusted, keyring: keyring,
                                           timeout: timeout)
        selection = Selection.new(mapping, indices, entries)
        entries.each do |entry|
          note = entry.pattern.difference_note(mapping.keys.sort)
          differs&.call(entry, note) if note
        end
        selection.unmatched.each { |entry| unmatched&.call(entry) }
        Result.new(selection: selection, path: Files.write_selection(output, selection))
      end

      # --release and --arch become file names: refused unless they are
      # names (a newline or ../ in them is no release of the data folder);
      # --os goes into messages and the files written.
      def check_names(release, arch, os)
        raise InvalidOption, "--os #{os.inspect} holds control characters" if os.to_s.match?(/\p{Cc}/)

        problem = Trust.release_name(release)
        raise InvalidOption, "--release #{problem}" if problem
        raise InvalidOption, "--arch #{arch.inspect} is not a Debian architecture name" unless arch.to_s.match?(/\A[a-z0-9][a-z0-9-]*\z/)
      end

      # The user's codename, to read repository URLs with.
      def codename(os)
        os.versions.find { |version| version.match?(/\A[a-z]+\z/) && version != "default" }
      end
      private_class_method :codename
    end
  end
end
