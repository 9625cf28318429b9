# frozen_string_literal: true

# Builds relspec's control-file reader (see deb822.c). bin/setup compiles it
# into lib/relspec/apt/; without it relspec uses the pure Ruby reader.
require "mkmf"

$CFLAGS << " -O2 -Wall -Wextra -Wno-unused-parameter"
create_makefile("relspec_deb822")
