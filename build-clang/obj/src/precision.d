build-clang/obj/src/precision.o: src/precision.c \
  include/shadecalc/precision.h

include/shadecalc/precision.h:
