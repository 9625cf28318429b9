# frozen_string_literal: true

require_relative "error"
require_relative "printable"

module Relspec
  # A path below a folder relspec writes into (a build's target folder, a
  # repository's report/ and abi/, a mirror) must not lead out of it
  # through a symbolic link relspec did not make: a write through a linked
  # folder lands in (and a clean-up deletes from) whatever folder the link
  # points to, and a read through a linked log copies any file of the
  # machine next to a published repository.
  module UnlinkedPath
    module_function

    # The first existing part of +relative+ below +base+ that is a
    # symbolic link, nil when none (what is missing is made later, by
    # relspec, as a plain folder or file).
    def first_link(base, relative)
      path = base
      relative.split("/").each do |part|
        path = File.join(path, part)
        return path if File.symlink?(path)
      end
      nil
    end

    # +relative+ below +base+, joined; raises +error+ naming the first link
    # on the way and where it points, followed by +why+ (what relspec does
    # there and what to do).
    def check(base, relative, why:, error: Error)
      link = first_link(base, relative)
      raise error, "#{Printable.text(link)} is a symbolic link (to #{Printable.text(File.readlink(link))}): #{why}" if link

      File.join(base, relative)
    end
  end
end
