# frozen_string_literal: true

module Relspec
  module CLI
    # The long help of the commands (`relspec help COMMAND`), kept apart
    # from Main, which only declares commands and options.
    module Help
      VALIDATE = <<~TEXT
        Reads each spec and all of its ancestors and reports every problem found,
        with file:line:column, the rule that failed and a hint. Works offline and
        writes nothing. Exits 1 if any error was found; warnings alone exit 0.
      TEXT

      SHOW = <<~TEXT
        Prints the release's own values merged with what it inherits from its
        parents (see docs/spec-reference.md). With --origins, each value is
        annotated with the file and line it comes from ("default" for built-in
        defaults).
      TEXT

      PLAN = <<~TEXT
        Reads the spec hierarchy, the workspace (or catalog snapshot) and what the
        ancestors' apt repositories hold, and prints per target how many packages
        are inherited, built and already published, then every build with its cause
        chain. --write records the plan in releases/<release>/lock.yml.
      TEXT

      COMPILE = <<~TEXT
        Plans the release, then writes one Debian source package (.orig.tar.gz,
        .debian.tar.xz, .dsc) per build decision into
        <out>/<release>/<codename>-<arch>/<source>/, plan.yml per target (the builds
        in dependency order), releases/<release>/lock.yml and the osdeps files. A
        compile with nothing changed writes nothing. First, the OS dependencies are
        checked as `relspec check` does (apt archives; Launchpad answers from its
        cache only): a release with missing ones is refused unless --no-check.
      TEXT

      PUBLISH = <<~TEXT
        Reads <out>/<release>/<codename>-<arch>/build-results.yml of each target and
        includes every built package (its .dsc and .debs; the -dbgsym .debs only with
        repository.debug_symbols: true) into the repository at the spec's
        repository.path, whose conf/distributions and conf/options it writes
        from the spec's targets (signed with repository.sign_with when set). Failed
        and skipped packages are never published; a file whose name the repository
        already holds with other bytes stops the publication before anything is
        included. Then writes <repository>/osdeps/<release>-<arch>.yml from what the
        repository really holds. Publishing the same results again changes nothing.
        See docs/publish.md.
      TEXT

      BUILD = <<~TEXT
        Reads <out>/<release>/<codename>-<arch>/plan.yml of each target and builds its
        source packages, a package as soon as its build-dependencies are built, up to
        --jobs at once. Results (status, version, duration, log, files with SHA256) go
        to build-results.yml in the target folder after every package; a killed run is
        resumed by the next one. sbuild's C and C++ compiles go through ccache when
        relspec runs as root (/var/cache/relspec/ccache; RELSPEC_CCACHE=DIR chooses
        another folder, RELSPEC_CCACHE=off none). An early cutoff candidate of plan.yml
        whose build closure left its interface unchanged is kept, not built (status
        kept; docs/abi.md); --rebuild-dependents builds every candidate. See docs/build.md.
      TEXT

      CHECK = <<~TEXT
        Every Build-Depends and Depends relation relspec writes for the packages the
        release builds must resolve on each target (by name, through Provides, or as an
        Architecture: all package). Sources: the distribution's apt archive
        (distributions.<codename>.archive; host: true for this machine's apt lists) or
        Launchpad for Ubuntu targets (auto: the archive where one is configured).
        Prints what is missing, with the packages that need it and a similar name that
        exists. Exits 1 when something is missing or a source could not answer.
        See docs/check.md.
      TEXT

      DIFF = <<~TEXT
        OLD and NEW are lock files, release folders (releases/<release>/) or specs (a
        spec is planned first). With --base REF, every release of specs/ (or those of
        the specs given) as committed at REF is compared with the working tree; REF is
        read with git, the working tree is not touched. Prints nothing when nothing
        differs. --exit-code: exit 0 without differences, 1 with, 2 on an error.
        --fail-on-rebuilds N: exit 1 when more than N packages are rebuilt.
        See docs/diff.md (the JSON schema) and docs/ci.md.
      TEXT
    end
  end
end
