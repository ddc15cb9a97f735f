build/obj/src/math/libm_shim.o: src/math/libm_shim.c \
 include/shadecalc/glsl.h
include/shadecalc/glsl.h:
