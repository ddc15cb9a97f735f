build-clang/obj/src/cli/cli_util.o: src/cli/cli_util.c src/cli/cli.h

src/cli/cli.h:
