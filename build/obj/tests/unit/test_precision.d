build/obj/tests/unit/test_precision.o: tests/unit/test_precision.c \
 include/shadecalc/precision.h
include/shadecalc/precision.h:
