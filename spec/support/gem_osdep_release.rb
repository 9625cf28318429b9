# frozen_string_literal: true

# The smallest release that reads its distribution's archive: a real
# autoproj workspace whose one package (tools/app, Ruby) has the gem osdep
# `foo`, and a reprepro archive for bookworm/amd64 holding one package.
# Planning asks the archive for ruby-foo, and gem_source when it lacks it.
module GemOsdepRelease
  module_function

  # Builds ws/ and the archive +archive+ (relative to +dir+) holding
  # +package+ ([name, version]).
  def build(dir, archive:, package:)
    builder = WorkspaceBuilder.new(File.join(dir, "ws"))
    builder.package("tools/app", type: :ruby, date: "2020-01-01T00:00:00Z", osdeps: ["foo"])
    builder.osdeps("foo:\n  gem: foo\n")
    builder.layout("tools/app")
    builder.create
    AptRepositoryBuilder.new(File.join(dir, archive), codenames: ["bookworm"], architectures: ["amd64"])
                        .add(*package, codename: "bookworm", arch: "amd64")
  end

  # The release's spec g (specs/g.yml of a folder beside the archive
  # ../debian) over the workspace #build made in +dir+; its gem_source a
  # closed port.
  def spec(dir)
    "release: g\nworkspace: #{dir}/ws/workspace\ntargets: { bookworm: [amd64] }\n" \
      "maintainer: Demo <demo@example.org>\ngem_source: http://127.0.0.1:1\n" \
      "distributions:\n  bookworm: { archive: { path: ../debian, trusted: true } }\n"
  end
end
