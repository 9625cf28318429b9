# frozen_string_literal: true

module Relspec
  class Catalog
    # The rake task autoproj runs to set up a Ruby package that compiles a C
    # extension (Autobuild::Ruby#rake_setup_task, "default" unless the
    # package set changes it), read after the package sets ran. autoproj runs
    # it in the checkout and uses the checkout's lib/ in place, so that is
    # where the compiled extension lands (tools/orocos.rb's rorocos.so, which
    # orocos.rb, syskit and everything above them require). A Debian package
    # built without it ships Ruby code whose extension is missing.
    #
    # Only packages with an extension (ext/<name>/extconf.rb and a
    # Rakefile) get one: the same task of a pure-Ruby package (often its
    # tests, or documentation) builds nothing the package installs.
    module RubyExtension
      # What a task name may be: it goes into debian/rules' rake command.
      TASK = /\A[A-Za-z0-9_][A-Za-z0-9_:.-]*\z/

      module_function

      # +autobuild+: the package after loading; nil unless it is a Ruby
      # package with an extension and a setup task.
      def setup_task(autobuild)
        return nil unless autobuild.is_a?(Autobuild::Ruby)

        task = autobuild.rake_setup_task
        return nil unless task.is_a?(String) && TASK.match?(task)

        dir = autobuild.srcdir
        return nil unless File.file?(File.join(dir, "Rakefile")) && !Dir.glob(File.join(dir, "ext", "*", "extconf.rb")).empty?

        task
      end

      # +package+'s task (Catalog::Package), checked again where it reaches
      # a command line of debian/rules: a catalog can be written by hand.
      def checked(package)
        task = package.extension_task
        return nil if task.nil?
        raise ArgumentError, "#{package.name}: bad rake task #{task.inspect}" unless TASK.match?(task)

        task
      end
    end
  end
end
