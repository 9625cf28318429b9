# frozen_string_literal: true

require "digest"

# Changes an index file of an (unsigned) repository and rewrites the
# SHA256 line of the Release file to match, to present a reader with files
# whose checksums are right but whose content is broken.
module ReleaseFileEditor
  module_function

  def replace_index(repository, codename, path, bytes)
    File.binwrite(File.join(repository, "dists", codename, path), bytes)
    release = File.join(repository, "dists", codename, "Release")
    text = File.read(release)
    text = text.gsub(/^ \h{64}\s+\d+ #{Regexp.escape(path)}$/) do
      " #{Digest::SHA256.hexdigest(bytes)} #{bytes.bytesize} #{path}"
    end
    File.write(release, text)
  end

  # Leaves only +path+ listed among the Packages indices of +directory+.
  def keep_only(repository, codename, directory, path)
    release = File.join(repository, "dists", codename, "Release")
    lines = File.read(release).lines.reject do |line|
      line.match?(%r{ #{Regexp.escape(directory)}/Packages(\.gz|\.xz)?$}) && !line.end_with?(" #{path}\n")
    end
    File.write(release, lines.join)
  end
end
