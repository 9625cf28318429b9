# frozen_string_literal: true

require "rexml/document"

module Relspec
  class Catalog
    # Who holds the copyright of a package, as its manifest.xml says: the
    # <copyright> element (one holder a line, "Name/email" as Rock writes
    # contacts), else the authors, else the maintainers. autoproj does not
    # read <copyright>, so it is read here. debian/copyright names these
    # upstream holders, never the release's maintainer.
    module CopyrightHolders
      module_function

      # +path+: the manifest.xml; +authors+, +maintainers+: [[name, email]].
      # Returns ["Name <email>", …] (may be empty).
      def of(path, authors, maintainers)
        listed = from_element(path)
        return listed unless listed.empty?

        contacts = authors.to_a.empty? ? maintainers.to_a : authors.to_a
        contacts.map { |name, email| contact(name, email) }.uniq
      end

      def from_element(path)
        return [] unless path && File.file?(path)

        element = REXML::Document.new(File.read(path)).root&.elements&.[]("copyright")
        return [] unless element

        element.text.to_s.lines.map(&:strip).reject(&:empty?).map do |line|
          name, email = line.split("/", 2)
          contact(name.strip, email&.strip)
        end.uniq
      rescue REXML::ParseException
        [] # autoproj already refused a broken manifest; nothing more to say here
      end

      def contact(name, email)
        email.nil? || email.empty? ? name : "#{name} <#{email}>"
      end
    end
  end
end
