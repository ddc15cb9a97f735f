build-clang/obj/src/cli/main.o: src/cli/main.c src/cli/cli.h \
  build-clang/gen/commands.h

src/cli/cli.h:

build-clang/gen/commands.h:
