# frozen_string_literal: true

# The trees of the early cutoff's corpus (CutoffCorpus): the library
# package's baseline, its dependent, and the debian/ of both.
module CutoffCorpus
  PREFIX = "/opt/rock/cutoff"

  # The baseline tree of cutoff-lib (path => content).
  def self.library
    {
      "Makefile" => <<~MAKE,
        PREFIX = #{PREFIX}
        CUT_SONAME = libcut.so.1
        CFLAGS ?= -g -O2
        CXXFLAGS ?= -g -O2
        all: libcut.so.1.0 libcutpp.so.1.0
        libcut.so.1.0: cut.c $(wildcard include/*.h)
        \t$(CC) $(CPPFLAGS) $(CFLAGS) -Iinclude -fPIC -shared -Wl,-soname,$(CUT_SONAME) $(LDFLAGS) -o $@ cut.c
        libcutpp.so.1.0: cutpp.cpp $(wildcard include/*.h)
        \t$(CXX) $(CPPFLAGS) $(CXXFLAGS) -Iinclude -fPIC -shared -Wl,-soname,libcutpp.so.1 $(LDFLAGS) -o $@ cutpp.cpp
        install:
        \tinstall -d $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/lib/cmake/cut $(DESTDIR)$(PREFIX)/include \\
        \t  $(DESTDIR)$(PREFIX)/share/orogen $(DESTDIR)$(PREFIX)/lib/ruby $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/cut
        \tinstall -m 644 libcut.so.1.0 libcutpp.so.1.0 $(DESTDIR)$(PREFIX)/lib/
        \tln -s libcut.so.1.0 $(DESTDIR)$(PREFIX)/lib/$(CUT_SONAME)
        \tln -s $(CUT_SONAME) $(DESTDIR)$(PREFIX)/lib/libcut.so
        \tln -s libcutpp.so.1.0 $(DESTDIR)$(PREFIX)/lib/libcutpp.so.1
        \tln -s libcutpp.so.1 $(DESTDIR)$(PREFIX)/lib/libcutpp.so
        \tinstall -m 644 include/*.h $(DESTDIR)$(PREFIX)/include/
        \tinstall -m 644 cut.pc $(DESTDIR)$(PREFIX)/lib/pkgconfig/
        \tinstall -m 644 cutConfig.cmake $(DESTDIR)$(PREFIX)/lib/cmake/cut/
        \tinstall -m 644 cut.tlb $(DESTDIR)$(PREFIX)/share/orogen/
        \tinstall -m 644 cut.rb $(DESTDIR)$(PREFIX)/lib/ruby/
        \tinstall -m 755 cut-gen $(DESTDIR)$(PREFIX)/bin/
        \tinstall -m 644 data.txt $(DESTDIR)$(PREFIX)/share/cut/
      MAKE
      "include/cut.h" => <<~C,
        #ifndef CUT_H
        #define CUT_H
        #define CUT_SCALE 10
        struct cut_point { int x; int y; };
        typedef int cut_count;
        enum cut_color { CUT_RED, CUT_GREEN, CUT_BLUE };
        static inline int cut_twice(int v) { return 2 * v; }
        int cut_value(void);
        int cut_sum(const struct cut_point *p);
        cut_count cut_count_of(int n);
        enum cut_color cut_favourite(void);
        int cut_old(void);
        struct cut_impl;
        struct cut_impl *cut_open(void);
        int cut_read(const struct cut_impl *impl);
        #endif
      C
      "include/cut_unused.h" => "#define CUT_UNUSED 1\n",
      "include/cutpp.h" => <<~CPP,
        #pragma once
        namespace cut {
        class Shape {
        public:
          virtual ~Shape();
          virtual int area() const;
          virtual int sides() const;
          int scaled(int factor = 2) const;
        };
        template <typename T> T twice(T v) { return v + v; }
        inline int triple(int v) { return 3 * v; }
        Shape *make_shape();
        }
      CPP
      "cut.c" => <<~C,
        #include "cut.h"
        /* the library's value */
        static int helper(int v) { return v; }
        /* exported, declared nowhere: only the ABI comparison sees it */
        int cut_hidden_counter = 3;
        int cut_value(void) { return helper(42); }
        int cut_sum(const struct cut_point *p) { return p->x + p->y; }
        cut_count cut_count_of(int n) { return n; }
        enum cut_color cut_favourite(void) { return CUT_BLUE; }
        int cut_old(void) { return 7; }
        /* private: users only hold a pointer to it */
        struct cut_impl { int x; };
        static struct cut_impl the_impl = { .x = 5 };
        struct cut_impl *cut_open(void) { return &the_impl; }
        int cut_read(const struct cut_impl *impl) { return impl->x; }
      C
      "cutpp.cpp" => <<~CPP,
        #include "cutpp.h"
        namespace cut {
        Shape::~Shape() {}
        int Shape::area() const { return 12; }
        int Shape::sides() const { return 4; }
        int Shape::scaled(int factor) const { return factor * area(); }
        Shape *make_shape() { return new Shape(); }
        }
      CPP
      "cut.pc" => "prefix=#{PREFIX}\nlibdir=${prefix}/lib\nincludedir=${prefix}/include\n\nName: cut\n" \
                  "Description: cutoff corpus\nVersion: 1.0\nLibs: -L${libdir} -lcut\nCflags: -I${includedir}\n",
      "cutConfig.cmake" => "set(CUT_INCLUDE_DIRS #{PREFIX}/include)\nset(CUT_LIBRARIES cut)\n",
      "cut.tlb" => "<?xml version=\"1.0\"?>\n<typelib>\n  <compound name=\"/cut_point\" size=\"8\">\n    " \
                   "<field name=\"x\" offset=\"0\" type=\"/int32_t\"/>\n    " \
                   "<field name=\"y\" offset=\"4\" type=\"/int32_t\"/>\n  </compound>\n</typelib>\n",
      "cut.rb" => "module Cut\n  SCALE = 10\nend\n",
      "cut-gen" => "#! /bin/sh\necho cut_point\n",
      "data.txt" => "red green blue\n",
      "README" => "cutoff corpus\n",
      "test/test_cut.c" => "#include \"cut.h\"\nint main(void) { return cut_value() == 42 ? 0 : 1; }\n"
    }
  end

  # The dependent's tree: two programs built against the installed
  # library (Build-Depends: cutoff-lib, laid over /opt by the host backend).
  def self.user
    {
      "Makefile" => <<~MAKE,
        P = #{PREFIX}
        all: cut-user cut-userpp
        cut-user: user.c
        \t$(CC) $(CPPFLAGS) $(CFLAGS) -I$(P)/include $(LDFLAGS) -o $@ user.c -L$(P)/lib -lcut
        cut-userpp: userpp.cpp
        \t$(CXX) $(CPPFLAGS) $(CXXFLAGS) -I$(P)/include $(LDFLAGS) -o $@ userpp.cpp -L$(P)/lib -lcutpp
        install:
        \tinstall -d $(DESTDIR)$(P)/bin
        \tinstall -m 755 cut-user cut-userpp $(DESTDIR)$(P)/bin/
      MAKE
      "user.c" => <<~C,
        #include <stdio.h>
        #include "cut.h"
        int main(void) {
          struct cut_point p = { 1, 2 };
          cut_count n = cut_count_of(5);
          printf("value %d sum %d twice %d scale %d colour %d count %d impl %d\\n", cut_value(), cut_sum(&p), cut_twice(5),
                 CUT_SCALE, (int)cut_favourite(), (int)n, cut_read(cut_open()));
          return 0;
        }
      C
      "userpp.cpp" => <<~CPP
        #include <cstdio>
        #include "cutpp.h"
        int main() {
          cut::Shape *shape = cut::make_shape();
          std::printf("area %d scaled %d twice %d triple %d\\n", shape->area(), shape->scaled(), cut::twice(4), cut::triple(3));
          delete shape;
          return 0;
        }
      CPP
    }
  end

  SKIPPED = %w[dh_auto_test dh_update_autotools_config dh_autoreconf dh_perl dh_strip_nondeterminism dh_dwz].freeze

  # debian/ of a package +name+ at +version+ (3.0 native); +depends+: its
  # Build-Depends on the library.
  def self.debian(name, version, build_depends: [])
    {
      "debian/source/format" => "3.0 (native)\n",
      "debian/changelog" => "#{name} (#{version}) bookworm; urgency=medium\n\n  * Corpus.\n\n " \
                            "-- Demo <demo@example.org>  Sun, 01 Mar 2020 00:00:00 +0000\n",
      "debian/control" => "Source: #{name}\nSection: libs\nPriority: optional\nMaintainer: Demo <demo@example.org>\n" \
                          "Build-Depends: #{(['debhelper-compat (= 13)'] + build_depends).join(', ')}\n" \
                          "Standards-Version: 4.6.2\nRules-Requires-Root: no\n\n" \
                          "Package: #{name}\nArchitecture: any\nDepends: ${shlibs:Depends}, ${misc:Depends}\n" \
                          "Description: early cutoff corpus\n a package of the corpus\n",
      "debian/rules" => "#!/usr/bin/make -f\n%:\n\tdh $@\n\n# /opt is no library folder dpkg knows\n" \
                        "override_dh_shlibdeps:\n\tdh_shlibdeps -- --ignore-missing-info -l#{PREFIX}/lib\n" \
                        "# steps that change nothing compared here, left out to keep the corpus cheap\n" \
                        "#{SKIPPED.map { |step| "override_#{step}:\n" }.join}",
      "debian/copyright" => "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n"
    }
  end
end
