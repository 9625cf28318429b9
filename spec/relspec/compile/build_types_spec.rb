# frozen_string_literal: true

require "spec_helper"

# The build types the demo workspace does not cover end to end: a Ruby
# package whose gemspec lists its files with `git ls-files` (as most Rock
# gemspecs do), and an oroGen component. Both are compiled from a real
# autoproj workspace and built with dpkg-buildpackage.
RSpec.describe "compiling Ruby gemspec and oroGen packages" do
  GEMSPEC = <<~RUBY
    Gem::Specification.new do |s|
      s.name = "rubylib"
      s.version = "0.4.0"
      s.summary = "A Ruby package of the test workspace"
      s.authors = ["Rock Packaging"]
      s.files = `git ls-files -z`.split("\\x0")
      s.bindir = "bin"
      s.executables = ["rubylib"]
    end
  RUBY
  # as orogen's: bin/ holds scripts, the gemspec declares no executables;
  # and as roby 3.1.0's, it asks for a Ruby this machine does not have
  # (autoproj never asks RubyGems, so the package is used all the same)
  TOOL_GEMSPEC = <<~RUBY
    Gem::Specification.new do |s|
      s.name = "gentool"
      s.version = "1.3.0"
      s.summary = "A generator run from its bin/"
      s.authors = ["Rock Packaging"]
      s.files = `git ls-files -z`.split("\\x0")
      s.require_paths = ["lib"]
      s.required_ruby_version = "2.5.0"
    end
  RUBY
  # a gemspec RubyGems cannot build: it lists a file the package lacks
  BROKEN_GEMSPEC = GEMSPEC.sub('"rubylib"', '"brokenlib"').sub(/s\.files = .*/, 's.files = ["lib/missing.rb"]')

  # as tools/orocos.rb's: a C extension that autoproj's setup task (rake
  # default) compiles into lib/, which .gitignore hides from the gemspec's list
  EXT_FILES = {
    "extlib.gemspec" => TOOL_GEMSPEC.sub('"gentool"', '"extlib"').sub('"1.3.0"', '"0.1.0"'),
    ".gitignore" => "*.so\n*.o\next/extlib/Makefile\n",
    "Rakefile" => <<~RUBY,
      task :default do
        sh "cd ext/extlib && ruby extconf.rb && make"
        mkdir_p "lib/extlib"
        cp "ext/extlib/extlib.so", "lib/extlib/extlib.so"
      end
    RUBY
    "ext/extlib/extconf.rb" => "require 'mkmf'\ncreate_makefile('extlib')\n",
    "ext/extlib/extlib.c" => "#include <ruby.h>\nstatic VALUE answer(VALUE self) { return INT2NUM(42); }\n" \
                             "void Init_extlib(void) { rb_define_global_function(\"extlib_answer\", answer, 0); }\n",
    "lib/extlib.rb" => "require 'extlib/extlib'\n"
  }.freeze

  # A stand-in for oroGen's generator: oroGen itself (and the Orocos
  # toolchain it needs) cannot be installed on this machine, so this script
  # does what debian/rules relies on: it generates a CMake project in the
  # package root from the .orogen file, and records its arguments.
  STAND_IN_OROGEN = <<~SH
    #!/bin/sh
    echo "$@" > orogen-arguments
    cat > CMakeLists.txt <<'EOF'
    cmake_minimum_required(VERSION 3.10)
    project(camera NONE)
    install(FILES camera.orogen orogen-arguments DESTINATION share/orogen)
    EOF
  SH

  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-types")
    builder = WorkspaceBuilder.new(File.join(@dir, "ws"))
    builder.package("tools/rubylib", type: :ruby, date: "2020-03-01T00:00:00Z", version: "0.4",
                                     files: { "rubylib.gemspec" => GEMSPEC, "lib/rubylib.rb" => "module Rubylib\nend\n",
                                              "bin/rubylib" => "#!/usr/bin/env ruby\nputs 'rubylib'\n" })
    builder.package("tools/gentool", type: :ruby, date: "2020-03-01T00:00:00Z", version: "1.3",
                                     files: { "gentool.gemspec" => TOOL_GEMSPEC,
                                              "lib/gentool.rb" => "module Gentool\n  ANSWER = 42\nend\n",
                                              "bin/gentool" => "#!/usr/bin/env ruby\nrequire 'gentool'\nputs Gentool::ANSWER\n" })
    builder.package("drivers/orogen/camera", type: :orogen, date: "2020-03-02T00:00:00Z",
                                             files: { "camera.orogen" => "name \"camera\"\n" })
    builder.package("tools/extlib", type: :ruby, date: "2020-03-01T00:00:00Z", version: "0.1", files: EXT_FILES)
    builder.package("tools/brokenlib", type: :ruby, date: "2020-03-01T00:00:00Z", version: "0.1",
                                       files: { "brokenlib.gemspec" => BROKEN_GEMSPEC, "lib/brokenlib.rb" => "\n" })
    builder.layout("tools/rubylib", "tools/gentool", "tools/extlib", "tools/brokenlib", "drivers/orogen/camera")
    builder.create
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "types.yml"), "release: types\nworkspace: ../ws/workspace\n" \
                                                      "targets: { bookworm: [amd64] }\nmaintainer: Demo <demo@example.org>\n")
    @run = relspec("compile", "specs/types.yml", "--out", "out", chdir: @dir)
    @tools = File.join(@dir, "tools")
    FileUtils.mkdir_p(@tools)
    File.write(File.join(@tools, "orogen"), STAND_IN_OROGEN)
    File.chmod(0o755, File.join(@tools, "orogen"))
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def build(deb, work)
    output, status = build_output(deb, work)
    expect(status).to be_success, output.lines.last(20).join
    Dir.glob(File.join(work, "#{deb}_*.deb")).first
  end

  def build_output(deb, work)
    dsc = Dir.glob(File.join(@dir, "out", "types", "bookworm-amd64", deb, "*.dsc")).first
    output, status = Open3.capture2e("dpkg-source", "-x", dsc, deb, chdir: work)
    raise output unless status.success?

    env = { "PATH" => "#{@tools}:#{ENV.fetch('PATH')}" }
    Open3.capture2e(env, "dpkg-buildpackage", "-us", "-uc", "-b", "-d", chdir: File.join(work, deb))
  end

  it "fails the build when the gem cannot be built, instead of shipping an empty package" do
    Dir.mktmpdir("relspec-ruby-broken") do |work|
      output, status = build_output("rock-types-ruby-tools-brokenlib", work)
      expect(status).not_to be_success
      expect(output).to include("lib/missing.rb")
      expect(Dir.glob(File.join(work, "*.deb"))).to eq([])
    end
  end

  def contents(deb)
    Open3.capture2("dpkg-deb", "-c", deb).first
  end

  it "builds a gem from a gemspec that asks git for its files" do
    expect(@run.exit_code).to eq(0), @run.stderr
    Dir.mktmpdir("relspec-ruby") do |work|
      deb = build("rock-types-ruby-tools-rubylib", work)
      prefix = "./opt/rock/types/rock-types-ruby-tools-rubylib"
      expect(contents(deb)).to include("#{prefix}/gems/gems/rubylib-0.4.0/lib/rubylib.rb",
                                       "#{prefix}/gems/specifications/rubylib-0.4.0.gemspec",
                                       "#{prefix}/bin/rubylib")
      expect(contents(deb)).not_to include("rubylib-0.4.0/debian/")
      # the throwaway repository and the built gem go away with `clean`
      tree = File.join(work, "rock-types-ruby-tools-rubylib")
      expect(File).to exist(File.join(tree, ".git", "relspec-throwaway"))
      output, status = Open3.capture2e("debian/rules", "clean", chdir: tree)
      expect(status).to be_success, output
      expect(Dir.children(tree).sort - [".pc"]).to eq(%w[bin debian lib manifest.xml rubylib.gemspec]) # .pc: dpkg-source's
    end
  end

  it "puts the bin/ of a gem that declares no executables on PATH, as autoproj does" do
    Dir.mktmpdir("relspec-ruby-bin") do |work|
      deb = build("rock-types-ruby-tools-gentool", work)
      root = File.join(work, "root")
      system("dpkg-deb", "-x", deb, root, exception: true)
      prefix = File.join(root, "opt/rock/types/rock-types-ruby-tools-gentool")
      expect(File.readlink(File.join(prefix, "bin"))).to eq("gems/gems/gentool-1.3.0/bin")
      # the installed env.sh's PATH and RUBYLIB, moved under the unpacked root
      env = File.read(File.join(prefix, "env.sh")).gsub("/opt/rock/types", File.join(root, "opt/rock/types"))
      File.write(File.join(work, "env.sh"), env)
      output, status = Open3.capture2e("sh", "-c", ". ./env.sh && gentool", chdir: work)
      expect([output, status.success?]).to eq(["42\n", true])
    end
  end

  it "compiles a Ruby package's C extension with autoproj's setup task and ships it" do
    Dir.mktmpdir("relspec-ruby-ext") do |work|
      deb = build("rock-types-ruby-tools-extlib", work)
      expect(File.basename(deb)).to end_with("_amd64.deb")
      root = File.join(work, "root")
      system("dpkg-deb", "-x", deb, root, exception: true)
      lib = File.join(root, "opt/rock/types/rock-types-ruby-tools-extlib/gems/gems/extlib-0.1.0/lib")
      expect(File.file?(File.join(lib, "extlib", "extlib.so"))).to be(true)
      output, status = Open3.capture2e(RbConfig.ruby, "-I", lib, "-e", 'require "extlib"; puts extlib_answer')
      expect([output, status.success?]).to eq(["42\n", true])
    end
  end

  it "runs the oroGen generator before configuring with CMake" do
    dsc = File.read(Dir[File.join(@dir, "out", "types", "bookworm-amd64", "rock-types-drivers-orogen-camera", "*.dsc")].first)
    # a clean chroot has no pkg-config, which the generator and its CMake ask
    expect(dsc[/^Build-Depends: (.*)$/, 1].split(", ")).to include("cmake", "pkg-config")
    Dir.mktmpdir("relspec-orogen") do |work|
      deb = build("rock-types-drivers-orogen-camera", work)
      share = "./opt/rock/types/rock-types-drivers-orogen-camera/share/orogen"
      expect(contents(deb)).to include("#{share}/camera.orogen", "#{share}/orogen-arguments")
      root = File.join(work, "root")
      system("dpkg-deb", "-x", deb, root, exception: true)
      arguments = File.read(File.join(root, share, "orogen-arguments"))
      # what autobuild would give it: this workspace's package sets set
      # nothing, so no --corba (Autobuild::Orogen.corba is unset)
      expect(arguments).to eq("--transports=corba,mqueue,typelib --type-export-policy=used camera.orogen\n")
    end
  end
end
