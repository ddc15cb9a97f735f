build/obj/src/cli/main.o: src/cli/main.c src/cli/cli.h \
 build/gen/commands.h
src/cli/cli.h:
build/gen/commands.h:
