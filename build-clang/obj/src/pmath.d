build-clang/obj/src/pmath.o: src/pmath.c include/shadecalc/pmath.h \
  include/shadecalc/precision.h include/shadecalc/glsl.h

include/shadecalc/pmath.h:

include/shadecalc/precision.h:

include/shadecalc/glsl.h:
