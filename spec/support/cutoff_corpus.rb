# frozen_string_literal: true

require_relative "cutoff_corpus_trees"

# The early cutoff's corpus (issue 45 item 3): one small real source
# package, cutoff-lib, that installs a C library (libcut), a C++ library
# (libcutpp) and the other things dependents build against (headers, a
# pkg-config file, a CMake config file, an oroGen type registry, a Ruby
# library, a generator, a data file) under /opt/rock/cutoff, and a
# dependent, cutoff-user, whose two programs include the headers, use the
# inline code, the templates, the macros and the types, and call into both
# libraries. Each case is an edit of cutoff-lib's tree; the spec builds
# the baseline and every case for real and asserts the early cutoff's
# decision on each.
module CutoffCorpus
  # A case: +name+; +edit+: path => [from, to] replacements (a nil +from+
  # writes the file, a nil +to+ removes it); +rebuild+: whether the
  # dependents must be rebuilt; +changed+: paths (under PREFIX) the
  # decision must name as changed; +abi+: the outcomes the library's ABI
  # comparison may give; +runs+: for kept cases, what the kept dependent's
  # two programs print against the new library.
  Case = Struct.new(:name, :edit, :rebuild, :changed, :abi, :runs, keyword_init: true)

  BASE_OUTPUT = ["value 42 sum 3 twice 10 scale 10 colour 2 count 5 impl 5", "area 12 scaled 24 twice 8 triple 9"].freeze

  def self.rebuild(name, edit, changed, abi: nil)
    Case.new(name: name, edit: edit, rebuild: true, changed: changed, abi: abi, runs: nil)
  end

  def self.keep(name, edit, runs: BASE_OUTPUT)
    Case.new(name: name, edit: edit, rebuild: false, changed: [], abi: nil, runs: runs)
  end

  CUT_H = "include/cut.h"
  CUTPP_H = "include/cutpp.h"
  HEADER = "include/cut.h"
  LIBCUT = "lib/libcut.so.1.0"
  LIBCUTPP = "lib/libcutpp.so.1.0"

  CASES = [
    rebuild("a struct member added", { CUT_H => ["struct cut_point { int x; int y; };",
                                                 "struct cut_point { int x; int y; int z; };"] }, [HEADER]),
    rebuild("struct members reordered", { CUT_H => ["struct cut_point { int x; int y; };",
                                                    "struct cut_point { int y; int x; };"] }, [HEADER]),
    rebuild("a virtual function added", { CUTPP_H => ["  virtual int sides() const;",
                                                      "  virtual int sides() const;\n  virtual int corners() const;"],
                                          "cutpp.cpp" => ["int Shape::sides() const { return 4; }",
                                                          "int Shape::sides() const { return 4; }\n" \
                                                          "int Shape::corners() const { return 4; }"] },
            [CUTPP_H, LIBCUTPP], abi: %i[changed incompatible]),
    rebuild("virtual functions reordered", { CUTPP_H => ["  virtual int area() const;\n  virtual int sides() const;",
                                                         "  virtual int sides() const;\n  virtual int area() const;"] },
            [CUTPP_H, LIBCUTPP], abi: %i[changed incompatible]),
    rebuild("an enum value inserted", { CUT_H => ["CUT_RED, CUT_GREEN", "CUT_RED, CUT_ORANGE, CUT_GREEN"] }, [HEADER]),
    rebuild("a default argument changed", { CUTPP_H => ["int factor = 2", "int factor = 3"] }, [CUTPP_H]),
    rebuild("an inline function's body changed in a header", { CUT_H => ["return 2 * v;", "return v << 1 | 0;"] }, [HEADER]),
    rebuild("a template's body changed in a header", { CUTPP_H => ["return v + v;", "return 2 * v;"] }, [CUTPP_H]),
    rebuild("a typedef changed", { CUT_H => ["typedef int cut_count;", "typedef long cut_count;"] }, [HEADER]),
    rebuild("a macro changed in a header", { CUT_H => ["#define CUT_SCALE 10", "#define CUT_SCALE 100"] }, [HEADER]),
    rebuild("a header added", { "include/cut_extra.h" => [nil, "#define CUT_EXTRA 1\n"] }, ["include/cut_extra.h"]),
    rebuild("a header removed", { "include/cut_unused.h" => [:all, nil] }, ["include/cut_unused.h"]),
    rebuild("a soname bump", { "Makefile" => ["CUT_SONAME = libcut.so.1", "CUT_SONAME = libcut.so.2"] },
            ["lib/libcut.so", "lib/libcut.so.1", "lib/libcut.so.2"]),
    rebuild("a symbol removed (its declaration left in the header)",
            { "cut.c" => ["int cut_old(void) { return 7; }\n", ""] }, [LIBCUT], abi: %i[incompatible]),
    rebuild("a symbol's signature changed", { CUT_H => ["int cut_sum(const struct cut_point *p);",
                                                        "long cut_sum(const struct cut_point *p, int scale);"],
                                              "cut.c" => ["int cut_sum(const struct cut_point *p) { return p->x + p->y; }",
                                                          "long cut_sum(const struct cut_point *p, int scale) " \
                                                          "{ return scale * (p->x + p->y); }"] },
            [HEADER, LIBCUT], abi: %i[changed incompatible]),
    rebuild("a .pc file's Libs changed", { "cut.pc" => ["Libs: -L${libdir} -lcut", "Libs: -L${libdir} -lcut -lm"] },
            ["lib/pkgconfig/cut.pc"]),
    rebuild("a .pc file's Cflags changed", { "cut.pc" => ["Cflags: -I${includedir}", "Cflags: -I${includedir} -DCUT_FAST"] },
            ["lib/pkgconfig/cut.pc"]),
    rebuild("a CMake config changed", { "cutConfig.cmake" => ["set(CUT_LIBRARIES cut)", "set(CUT_LIBRARIES cut m)"] },
            ["lib/cmake/cut/cutConfig.cmake"]),
    rebuild("an oroGen typekit type changed", { "cut.tlb" => ['<field name="x" offset="0" type="/int32_t"/>',
                                                              '<field name="x" offset="0" type="/int64_t"/>'] },
            ["share/orogen/cut.tlb"]),
    rebuild("a Ruby library file changed", { "cut.rb" => ["SCALE = 10", "SCALE = 100"] }, ["lib/ruby/cut.rb"]),
    rebuild("a generator changed", { "cut-gen" => ["echo cut_point", "echo cut_point cut_color"] }, ["bin/cut-gen"]),
    rebuild("a data file changed", { "data.txt" => ["red green blue", "red orange green blue"] }, ["share/cut/data.txt"]),
    rebuild("an exported variable's type changed (the header unchanged)",
            { "cut.c" => ["int cut_hidden_counter = 3;", "long long cut_hidden_counter = 3;"] },
            [LIBCUT], abi: %i[changed incompatible]),
    keep("a function body changed in a .c", { "cut.c" => ["return helper(42);", "return helper(43);"] },
         runs: [BASE_OUTPUT[0].sub("value 42", "value 43"), BASE_OUTPUT[1]]),
    keep("a function body changed in a .cpp", { "cutpp.cpp" => ["int Shape::area() const { return 12; }",
                                                                "int Shape::area() const { return 13; }"] },
         runs: [BASE_OUTPUT[0], BASE_OUTPUT[1].sub("area 12 scaled 24", "area 13 scaled 26")]),
    keep("a comment changed in a source file", { "cut.c" => ["/* the library's value */", "/* the value, documented */"] }),
    keep("a test and the README changed", { "README" => ["cutoff corpus", "cutoff corpus, explained"],
                                            "test/test_cut.c" => ["return cut_value() == 42 ? 0 : 1;",
                                                                  "return cut_value() != 42;"] }),
    keep("a private function changed", { "cut.c" => ["static int helper(int v) { return v; }",
                                                     "static int helper(int v) { return v + 0 * (v >> 1); }"] }),
    keep("a private type behind a pointer changed (abidiff sees it; no installed header defines it)",
         { "cut.c" => ["struct cut_impl { int x; };", "struct cut_impl { long cache; int x; };"] }),
    keep("a new exported function nothing uses", { "cut.c" => ["int cut_old(void) { return 7; }",
                                                               "int cut_old(void) { return 7; }\nint cut_new(void) { return 8; }"] })
  ].freeze

  # +tree+ with +edit+ applied (see Case); raises when a replacement finds
  # nothing to replace, so that a case never silently tests the baseline.
  def self.edited(tree, edit)
    edit.each_with_object(tree.dup) do |(path, (from, to)), out|
      if from.nil? then out[path] = to
      elsif to.nil? then out.delete(path) || raise("#{path} is not in the tree")
      else
        raise "#{from.inspect} is not in #{path}" unless out.fetch(path).include?(from)

        out[path] = out[path].sub(from) { to }
      end
    end
  end
end
