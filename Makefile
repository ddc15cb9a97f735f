# shadecalc — build, test, run, benchmark, install.
#
#   make run      build, then the main job (a tour of what shadecalc computes)
#   make check    build, then every test: unit, end-to-end, sanitizers, fuzz smoke
#
# Sources are found by folder, so a new file needs no edit here:
#   src/**/*.c         the library (src/cli/ excluded)
#   src/simd/avx2/     compiled with -mavx2 -mfma -mf16c   (x86-64 only)
#   src/simd/sse41/    compiled with -msse4.1              (x86-64 only)
#   src/simd/avx512/   compiled with -mavx512f -mavx512dq -mfma (x86-64 only)
#   src/simd/scalar/   compiled with -fno-math-errno: the lanes' sqrtf become one vector sqrt
#   src/cli/*.c        the shadecalc binary; src/cli/cmd_NAME.c is subcommand NAME
#   tests/unit/test_*.c   one cmocka binary each, linked with tests/support/*.c
#   tests/e2e/test_*.sh   end-to-end tests of the binary
#   tests/fuzz/fuzz_*.c   libFuzzer harnesses (built with clang), linked with tests/support/*.c
#   bench/*.c          the benchmark harness, linked into the shadecalc binary
#   bench/programs/*.c standalone programs, one main each (accuracy_table)

# The version is written once, in include/shadecalc/version.h.
VERSION   := $(shell sed -n 's/^\#define SC_VERSION_\(MAJOR\|MINOR\|PATCH\) *//p' \
               include/shadecalc/version.h | paste -sd.)
SOVERSION := $(firstword $(subst ., ,$(VERSION)))
PREFIX    ?= /usr/local
DESTDIR   ?=

CC       ?= cc
CCNAME   := $(notdir $(firstword $(CC)))
ifeq ($(CCNAME),cc)
BUILD    ?= build
else
BUILD    ?= build-$(CCNAME)
endif

WARN     := -std=c11 -Wall -Wextra -Wpedantic -Werror
OPT      ?= -O2 -g
# FMA only where written (fma(), intrinsics): both compilers give the same bits.
FPFLAGS  := -ffp-contract=off
CPPFLAGS += -Iinclude -Isrc -I. -I$(BUILD)/gen -D_POSIX_C_SOURCE=200809L -DSC_VERSION=\"$(VERSION)\"
ifeq ($(SAN),1)
SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
endif
ifeq ($(SAN),thread)
SANFLAGS := -fsanitize=thread -fno-omit-frame-pointer
endif
ALLCFLAGS = $(WARN) $(OPT) $(FPFLAGS) -fPIC -pthread $(SANFLAGS) $(CFLAGS)
EXR_LIBS  = $(shell pkg-config --libs-only-l OpenEXR 2>/dev/null | tr ' ' '\n' | grep OpenEXRCore)
LDLIBS   += $(EXR_LIBS) -lm -lpthread
LDALL     = $(SANFLAGS) -pthread $(LDFLAGS)

# The SIMD kernel files inline hundreds of specialised loops: with full debug information (-g)
# gcc 12 spent 131 s of CPU on the AVX2 kernels (then one file), with line tables only (-g1)
# 63 s, about what it takes without -g (61 s); backtraces keep their file and line.
$(BUILD)/obj/src/simd/%.o: SIMD_DEBUG := -g1
# Under the sanitizers, clang 14 spent 112 s of CPU on the AVX2 kernels at -O2 and 80 s at
# -O1: the sanitizer tree builds the kernel files at -O1 (its tests run a 1/50 sample).
ifeq ($(SAN),1)
$(BUILD)/obj/src/simd/%.o: SIMD_DEBUG := -g1 -O1
endif
# The instrumentation is most of that time: clang 14 -O1 spent 28.9 CPU-s on
# src/simd/avx512/shade_bits12.c with ASan+UBSan, 5.3 without. On a host that cannot run the
# AVX-512 kernels (no AVX-512 F and DQ: the tests skip them), the sanitizer tree compiles them
# without it, with -Werror still; on a host that runs them, instrumented.
HOST_AVX512 ?= $(shell $(CC) -march=native -dM -E -x c /dev/null 2>/dev/null | grep -cE '__AVX512(F|DQ)__')
ifeq ($(SAN),1)
ifneq ($(HOST_AVX512),2)
$(BUILD)/obj/src/simd/avx512/%.o: SANFLAGS :=
endif
endif

# Portable C: a sqrtf that need not set errno is the target's vector square root, where each
# lane's call was a scalar sqrtss and a test for a negative input (sqrt 1.23 -> 0.31 ns per
# element, the accurate shading tier 1.4-2x faster, on x86-64).
$(BUILD)/obj/src/simd/scalar/%.o: ISAFLAGS := -fno-math-errno
ARCH := $(shell uname -m)
ifneq ($(filter x86_64 amd64 i686 i386,$(ARCH)),)
$(BUILD)/obj/src/simd/avx2/%.o: ISAFLAGS := -mavx2 -mfma -mf16c
$(BUILD)/obj/src/simd/sse41/%.o: ISAFLAGS := -msse4.1
$(BUILD)/obj/src/simd/avx512/%.o: ISAFLAGS := -mavx512f -mavx512dq -mfma
$(BUILD)/obj/bench/sleef_avx2.o: ISAFLAGS := -mavx2 -mfma
$(BUILD)/obj/bench/peak_avx2.o: ISAFLAGS := -mavx2 -mfma
$(BUILD)/obj/bench/fastmath_%_avx2.o: ISAFLAGS = $(FASTMATH_AVX2)
endif

# The plain loops of bench/libm_loops.c again as a user who tries -O3 -march=native -ffast-math
# gets them, by gcc and by clang when each is installed, whatever CC is (peer rows of
# `shadecalc bench`), and with -mavx2 -mfma (x86-64: the peers of the AVX2 tiers); not
# instrumented by the sanitizers, whose runtimes differ between the two compilers.
FASTMATH ?= -O3 -march=native -ffast-math -ffp-contract=fast
FASTMATH_AVX2 := -O3 -mavx2 -mfma -ffast-math -ffp-contract=fast
$(BUILD)/obj/bench/fastmath_%.o: ISAFLAGS := $(FASTMATH)
$(BUILD)/obj/bench/fastmath_%.o: SANFLAGS :=
$(BUILD)/obj/bench/fastmath_gcc.o $(BUILD)/obj/bench/fastmath_gcc_avx2.o: \
    override CC := $(if $(shell command -v gcc),gcc,$(CC))
$(BUILD)/obj/bench/fastmath_clang.o $(BUILD)/obj/bench/fastmath_clang_avx2.o: \
    override CC := $(if $(shell command -v clang),clang,$(CC))
$(BUILD)/obj/bench/report.o: CPPFLAGS += \
    -DSC_BENCH_FLAGS='"$(OPT) $(FPFLAGS); peers $(FASTMATH), $(FASTMATH_AVX2)"'

# SLEEF (libsleef-dev) is optional: when found, `shadecalc bench` also times its AVX2 functions.
# NO_SLEEF=1 builds as if it were absent (the tests must pass either way).
ifneq ($(NO_SLEEF),1)
SLEEF_LIBS := $(shell pkg-config --libs sleef 2>/dev/null)
endif
ifneq ($(SLEEF_LIBS),)
$(BUILD)/obj/bench/sleef_avx2.o: CPPFLAGS += -DSC_HAVE_SLEEF
BIN_LIBS := $(SLEEF_LIBS)
endif

# Mesa's llvmpipe, the GLSL ES reference of tests/e2e/test_mesa.sh (tests/mesa/), is built when
# pkg-config finds EGL and GLES (Debian's libegl-dev, libgles-dev); the test skips without it.
# Not instrumented by the sanitizers: it is a reference, and Mesa's own allocations would be
# reported as leaks.
MESA_LIBS := $(shell pkg-config --libs egl glesv2 2>/dev/null)
ifneq ($(MESA_LIBS),)
MESA_EVAL := $(BUILD)/tests/mesa_eval
endif
$(BUILD)/tests/mesa_eval: SANFLAGS :=

# The detected configuration (compiler, flags, optional libraries) is kept in a stamp that every
# object and link depends on: when it changes (libsleef-dev installed, CFLAGS=...), what depends
# on it is rebuilt without a `make clean`.
CONFIG_STAMP := $(BUILD)/config.stamp
CONFIG_TEXT   = $(CC) [$(shell $(CC) --version 2>/dev/null | head -n 1)] $(CPPFLAGS) $(ALLCFLAGS) \
                $(LDFLAGS) exr[$(EXR_LIBS)] sleef[$(SLEEF_LIBS)] peers[$(FASTMATH)] mesa[$(MESA_LIBS)]
ifneq ($(CONFIG_TEXT),$(file <$(CONFIG_STAMP)))
$(shell mkdir -p $(BUILD))
$(file >$(CONFIG_STAMP),$(CONFIG_TEXT))
endif
$(CONFIG_STAMP): ;

LIB_SRCS   := $(sort $(shell find src -name '*.c' ! -path 'src/cli/*'))
CLI_SRCS   := $(sort $(wildcard src/cli/*.c))
CMD_SRCS   := $(sort $(wildcard src/cli/cmd_*.c))
SUP_SRCS   := $(sort $(wildcard tests/support/*.c))
UNIT_SRCS  := $(sort $(wildcard tests/unit/test_*.c))
BENCH_SRCS := $(sort $(wildcard bench/*.c))
PROG_SRCS  := $(sort $(wildcard bench/programs/*.c))
FUZZ_SRCS  := $(sort $(wildcard tests/fuzz/fuzz_*.c))

obj = $(patsubst %.c,$(BUILD)/obj/%.o,$(1))
# The longest compiles first, so that make -j does not end on one of them alone: the shading
# kernel's files (src/simd/*/shade_*.c), then the other kernels' (src/simd/*/kernels.c).
SLOW_SRCS  := $(sort $(wildcard src/simd/*/shade_*.c)) $(sort $(wildcard src/simd/*/kernels.c))
LIB_OBJS   := $(call obj,$(SLOW_SRCS) $(filter-out $(SLOW_SRCS),$(LIB_SRCS)))
CLI_OBJS   := $(call obj,$(CLI_SRCS) $(BENCH_SRCS))
SUP_OBJS   := $(call obj,$(SUP_SRCS))
UNIT_BINS  := $(patsubst tests/unit/%.c,$(BUILD)/tests/%,$(UNIT_SRCS))
PROG_BINS  := $(patsubst bench/programs/%.c,$(BUILD)/bench/%,$(PROG_SRCS))

STATIC := $(BUILD)/libshadecalc.a
SHARED := $(BUILD)/libshadecalc.so.$(VERSION)
SONAME := libshadecalc.so.$(SOVERSION)
BIN    := $(BUILD)/shadecalc

.PHONY: all deps check check-valgrind coverage unit e2e san fuzz run bench accuracy install uninstall format clean
.DEFAULT_GOAL := all
.SECONDARY:

all: deps
	@$(MAKE) --no-print-directory build-all

.PHONY: build-all
build-all: $(STATIC) $(SHARED) $(BIN) $(PROG_BINS)

deps:
	@sh mk/deps.sh

# The library exports what the public headers declare (shadecalc/api.h), nothing else; its
# objects depend on api.h, so that objects compiled before that rule are compiled again.
$(LIB_OBJS): VISFLAGS := -fvisibility=hidden
$(LIB_OBJS): include/shadecalc/api.h

$(BUILD)/obj/%.o: %.c $(CONFIG_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALLCFLAGS) $(SIMD_DEBUG) $(ISAFLAGS) $(VISFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/gen/commands.h: $(CMD_SRCS) mk/gen-commands.sh
	@mkdir -p $(dir $@)
	sh mk/gen-commands.sh $(CMD_SRCS) > $@.tmp && mv $@.tmp $@

$(CLI_OBJS): $(BUILD)/gen/commands.h

$(STATIC): $(LIB_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

$(SHARED): $(LIB_OBJS)
	$(CC) -shared -Wl,-soname,$(SONAME) $(LDALL) -o $@ $^ $(LDLIBS)
	ln -sf $(notdir $@) $(BUILD)/$(SONAME)
	ln -sf $(SONAME) $(BUILD)/libshadecalc.so

$(BIN): $(CLI_OBJS) $(STATIC)
	$(CC) $(LDALL) -o $@ $(CLI_OBJS) $(STATIC) $(BIN_LIBS) $(LDLIBS)

$(BUILD)/tests/%: $(BUILD)/obj/tests/unit/%.o $(SUP_OBJS) $(STATIC)
	@mkdir -p $(dir $@)
	$(CC) $(LDALL) -o $@ $< $(SUP_OBJS) $(STATIC) -lcmocka $(LDLIBS)

$(BUILD)/tests/mesa_eval: $(BUILD)/obj/tests/mesa/mesa_eval.o
	@mkdir -p $(dir $@)
	$(CC) $(LDALL) -o $@ $< $(MESA_LIBS)

$(BUILD)/bench/%: $(BUILD)/obj/bench/programs/%.o $(STATIC)
	@mkdir -p $(dir $@)
	$(CC) $(LDALL) -o $@ $< $(STATIC) $(LDLIBS)

# ---- tests -------------------------------------------------------------------
# `check` = unit + e2e with this compiler, the same under ASan+UBSan built with the other
# compiler (gcc and clang: so both compile every file with -Werror), then the fuzz smoke.
# Each stage builds in parallel (JOBS, default the number of processors), then runs its tests
# in parallel too: every unit binary and every e2e script is a make target of its own
# (tests/run-test.sh keeps its output in $(BUILD)/results/ and prints it when it fails), so
# the reports do not interleave. Under the sanitizers the unit tests' large numeric sweeps run
# a deterministic 1/50 sample (tests/unit/scale.h); the plain stage checks every bound on all
# 10^6 inputs per kernel, tier and instruction set.
# Most of check's CPU is compiling the SIMD kernels of src/simd/: in a fresh clone, when each
# instruction set was one file, the gcc tree took 318 CPU-s, 256 of them for scalar, sse41, avx2
# and avx512 (60-73 s each); clang with ASan+UBSan 156 s for avx2, 137 s for avx512, 39 s for
# the 81 other files. Each is now three files (src/simd/kernel_group.h), a make -j job each:
# gcc 12 took 159 CPU-s for the twelve, 233 s when the shading kernel's bits8 tier made four.
# The plain unit and e2e tests and lib-tests took 191 CPU-s (all 10^6 inputs; test_batch_light
# and test_batch the heaviest).
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
# The sanitizer tree's compiler: the other of gcc and clang, or CC itself when that one is not
# installed (check says so). When it is clang, the fuzz tree takes its SIMD kernel objects.
OTHER_CC := $(if $(filter clang%,$(CCNAME)),gcc,clang)
SAN_CC   ?= $(if $(shell command -v $(OTHER_CC)),$(OTHER_CC),$(CC))
SAN_VARS := SAN=1 BUILD=$(BUILD)-san CC=$(SAN_CC)
check: deps
	@$(MAKE) --no-print-directory format-check
	@$(MAKE) --no-print-directory -j$(JOBS) test-bins build-all
	@$(MAKE) --no-print-directory tests lib-tests
	@[ "$(SAN_CC)" != "$(CC)" ] || echo "check: $(OTHER_CC) not installed: the sanitizer stage is built with $(CC) too"
	@$(MAKE) --no-print-directory -j$(JOBS) $(SAN_VARS) test-bins build-all
	@$(MAKE) --no-print-directory $(SAN_VARS) tests
	@$(MAKE) --no-print-directory fuzz $(if $(filter $(FUZZ_CC),$(SAN_CC)),FUZZ_SIMD_FROM=$(BUILD)-san)
	@echo "check: all test stages passed ($(CCNAME), sanitizers: $(notdir $(firstword $(SAN_CC))))"

# A fresh clone of HEAD in an empty directory, checked with and without the optional SLEEF.
.PHONY: check-fresh
check-fresh:
	@sh mk/fresh-clone.sh

.PHONY: test-bins
test-bins: $(STATIC) $(UNIT_BINS) $(BIN) $(MESA_EVAL)

# One phony target per test: unit/test_NAME runs a binary, e2e/test_NAME a script. The
# heaviest come first, so that the last to finish are short ones.
RESULTS     := $(BUILD)/results
HEAVY_UNITS := test_batch_light test_batch test_shortest test_exhaustive test_batch_area \
               test_math_accuracy test_check test_image test_ltc
UNIT_NAMES  := $(foreach t,$(HEAVY_UNITS),$(filter $(t),$(notdir $(UNIT_BINS)))) \
               $(filter-out $(HEAVY_UNITS),$(notdir $(UNIT_BINS)))
E2E_NAMES   := $(patsubst tests/e2e/%.sh,%,$(sort $(wildcard tests/e2e/test_*.sh)))
UNIT_RUNS   := $(addprefix unit/,$(UNIT_NAMES))
E2E_RUNS    := $(addprefix e2e/,$(E2E_NAMES))
.PHONY: tests $(UNIT_RUNS) $(E2E_RUNS)

# $(call run_pool,KINDS,TARGETS): fresh results for KINDS (unit, e2e), then TARGETS JOBS at a
# time; $(call summary,KIND,NAMES): the counts of a kind, failing when one failed.
run_pool = rm -rf $(addprefix $(RESULTS)/,$(1)); $(MAKE) --no-print-directory -j$(JOBS) -Otarget $(2)
summary  = sh tests/run-test.sh --summary $(RESULTS)/$(1) $(1) $(2)

unit: $(UNIT_BINS)
	@$(call run_pool,unit,$(UNIT_RUNS)); $(call summary,unit,$(UNIT_NAMES))

e2e: $(BIN) $(MESA_EVAL)
	@$(call run_pool,e2e,$(E2E_RUNS)); $(call summary,e2e,$(E2E_NAMES))

# unit and e2e in one pool of JOBS (check): no core waits for the other stage's last test.
tests: $(UNIT_BINS) $(BIN) $(MESA_EVAL)
	@$(call run_pool,unit e2e,$(UNIT_RUNS) $(E2E_RUNS)); ok=1; \
	    $(call summary,unit,$(UNIT_NAMES)) || ok=0; $(call summary,e2e,$(E2E_NAMES)) && [ $$ok = 1 ]

$(UNIT_RUNS): unit/%:
	@sh tests/run-test.sh $(RESULTS)/unit $* $(BUILD)/tests/$*

$(E2E_RUNS): e2e/%:
	@SHADECALC=$(abspath $(BIN)) sh tests/run-test.sh $(RESULTS)/e2e $* sh tests/e2e/$*.sh

# The library as its users see it: the exported symbols against the headers, every header
# alone in C and C++, then an install into a temporary prefix used through pkg-config.
.PHONY: lib-tests
lib-tests: build-all
	@sh tests/install/exports.sh $(BUILD) '$(CC)'
	@sh tests/install/run.sh '$(MAKE)' '$(CC)'

# memcheck over the end-to-end tests (not part of check: it takes many minutes), on a build of
# its own with DWARF 4 debug information (valgrind 3.19 does not read every DWARF 5 form) and
# the bench's fast-math peers at AVX2 rather than -march=native (valgrind has no AVX-512).
VG_BUILD := build-valgrind
check-valgrind: deps
	@$(MAKE) --no-print-directory -j$(JOBS) BUILD=$(VG_BUILD) OPT="-O2 -gdwarf-4" \
	    FASTMATH="-O3 -mavx2 -mfma -ffast-math -ffp-contract=fast" $(VG_BUILD)/shadecalc
	@sh tests/e2e/valgrind.sh $(VG_BUILD)/shadecalc

# libFuzzer harnesses, built with clang against an instrumented copy of the library:
# a bounded smoke run in `check`; `make fuzz FUZZ_SECONDS=600` for a long one.
FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 10
FUZZ_BINS    := $(patsubst tests/fuzz/%.c,build-fuzz/fuzz/%,$(FUZZ_SRCS))
ifeq ($(FUZZ),1)
SANFLAGS += -fsanitize=fuzzer-no-link
endif

# The harnesses run in parallel, JOBS at a time (one target each).
FUZZ_RUNS    := $(patsubst tests/fuzz/%.c,fuzz/%,$(FUZZ_SRCS))
.PHONY: $(FUZZ_RUNS)
fuzz: deps
	@$(MAKE) --no-print-directory -j$(JOBS) CC=$(FUZZ_CC) BUILD=build-fuzz SAN=1 FUZZ=1 \
	    $(if $(FUZZ_SIMD_FROM),FUZZ_SIMD_FROM=$(FUZZ_SIMD_FROM)) fuzz-bins
	@$(MAKE) --no-print-directory -j$(JOBS) -Otarget $(FUZZ_RUNS)
	@echo "fuzz: $(words $(FUZZ_RUNS)) passed, 0 failed"

$(FUZZ_RUNS): fuzz/%:
	@sh tests/fuzz/run.sh $(FUZZ_SECONDS) build-fuzz/fuzz/$*

.PHONY: fuzz-bins
fuzz-bins: $(FUZZ_BINS)

# FUZZ_SIMD_FROM=TREE (check): the SIMD kernel objects are those of TREE, built by the same
# compiler with the same sanitizers, without the fuzzer's coverage (the parsers are fuzzed, not
# the kernels): they are the most of a tree's compile time.
ifneq ($(and $(FUZZ_SIMD_FROM),$(filter 1,$(FUZZ))),)
$(BUILD)/obj/src/simd/%.o: $(FUZZ_SIMD_FROM)/obj/src/simd/%.o
	@mkdir -p $(dir $@)
	cp $< $@
endif

build-fuzz/fuzz/%: $(BUILD)/obj/tests/fuzz/%.o $(SUP_OBJS) $(STATIC)
	@mkdir -p $(dir $@)
	$(CC) $(LDALL) -fsanitize=fuzzer -o $@ $< $(SUP_OBJS) $(STATIC) $(LDLIBS)

# Line and branch coverage of the unit and end-to-end tests (gcovr, a test-only dependency):
# an -O0 --coverage build in build-cov/, a table per file, and the targets of mk/coverage.py.
# The bound checks of test_batch and test_math_accuracy run 10^4 inputs per kernel instead of
# 10^6 (the same code paths; `make unit` checks the bounds on all of them). The SIMD helpers are
# not force-inlined (src/simd/kernels_impl.h), so their branches are counted once per ISA.
COV_BUILD := build-cov
COV_VARS  := BUILD=$(COV_BUILD) OPT="-O0 -g" CFLAGS="--coverage -DSC_NO_ALWAYS_INLINE" \
             LDFLAGS="--coverage"
COV_INPUTS := SHADECALC_BATCH_INPUTS=10000 SHADECALC_ACCURACY_INPUTS=10000
coverage: deps
	@command -v gcovr >/dev/null || { echo "coverage: gcovr is not installed (make deps as root installs it)" >&2; exit 1; }
	@rm -rf $(COV_BUILD)/obj $(COV_BUILD)/coverage.json
	@$(MAKE) --no-print-directory -j$(JOBS) $(COV_VARS) test-bins
	@$(COV_INPUTS) $(MAKE) --no-print-directory $(COV_VARS) unit e2e
	@gcovr --root . --filter src/ --object-directory $(COV_BUILD)/obj \
	    --exclude-unreachable-branches --exclude-throw-branches \
	    --json-summary $(COV_BUILD)/coverage.json --html-details $(COV_BUILD)/coverage.html
	@python3 mk/coverage.py $(COV_BUILD)/coverage.json

# ---- the main job, benchmarks, accuracy table ---------------------------------
run: all
	@sh mk/tour.sh $(BIN)

bench: all
	@sh mk/bench.sh $(BUILD)

accuracy: all
	$(BUILD)/bench/accuracy_table

# sweep against an awk one-liner printing the same curve: ROWS and ROUNDS in BENCH_SWEEP_ARGS.
.PHONY: bench-sweep
bench-sweep: all
	$(BUILD)/bench/sweep_vs_awk $(BIN) $(BENCH_SWEEP_ARGS)

# The Disney BRDF in GLSL (bench/programs/disney.glsl) by block execution against the same code
# in C at -O2 and the built-in cook-torrance GGX, ns per evaluation on one thread.
.PHONY: bench-brdf
bench-brdf: all
	$(BUILD)/bench/brdf_disney bench/programs/disney.glsl $(BENCH_BRDF_ARGS)

# ---- correct rounding over every binary32 input (tests/exhaustive/, MPFR) ------------------
# Not part of check: hours of CPU (about 8 h wall on 2 shared cores) (EXHAUSTIVE_ARGS="--stride 257" for a sample).
# check runs the same checker on a sample (tests/unit/test_exhaustive.c).
EXH_OBJS := $(call obj,$(filter-out tests/exhaustive/main.c,$(wildcard tests/exhaustive/*.c)))
EXH_LIBS := -lmpfr -lgmp
.PHONY: exhaustive
exhaustive: deps
	@$(MAKE) --no-print-directory -j$(JOBS) $(BUILD)/tests/exhaustive
	$(BUILD)/tests/exhaustive --outdir $(BUILD)/exhaustive $(EXHAUSTIVE_ARGS)

$(BUILD)/tests/exhaustive: $(BUILD)/obj/tests/exhaustive/main.o $(EXH_OBJS) $(STATIC)
	$(CC) $(LDALL) -o $@ $^ $(EXH_LIBS) $(LDLIBS)

$(BUILD)/tests/test_exhaustive: $(EXH_OBJS)
$(BUILD)/tests/test_exhaustive: SUP_OBJS += $(EXH_OBJS)
$(BUILD)/tests/test_exhaustive: LDLIBS := $(EXH_LIBS) $(LDLIBS)

# test_shortest runs the checker of `--groups print` (no MPFR) on binary16 and on samples.
SHORTEST_CHECK := $(call obj,tests/exhaustive/shortest_check.c tests/exhaustive/shortest_exact.c)
$(BUILD)/tests/test_shortest: $(SHORTEST_CHECK)
$(BUILD)/tests/test_shortest: SUP_OBJS += $(SHORTEST_CHECK)
# test_shortest_check: the exact checker of `--groups print` against the libc one.
$(BUILD)/tests/test_shortest_check: $(SHORTEST_CHECK)
$(BUILD)/tests/test_shortest_check: SUP_OBJS += $(SHORTEST_CHECK)

# ---- install -----------------------------------------------------------------
LIBDIR := $(DESTDIR)$(PREFIX)/lib
install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/include/shadecalc $(LIBDIR)/pkgconfig \
	    $(DESTDIR)$(PREFIX)/share/man/man1 $(DESTDIR)$(PREFIX)/share/man/man3
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/shadecalc
	install -m 644 include/shadecalc/*.h $(DESTDIR)$(PREFIX)/include/shadecalc/
	install -m 644 $(STATIC) $(LIBDIR)/
	install -m 755 $(SHARED) $(LIBDIR)/
	ln -sf libshadecalc.so.$(VERSION) $(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(LIBDIR)/libshadecalc.so
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|' -e 's|@EXR@|$(EXR_LIBS)|' \
	    mk/shadecalc.pc.in > $(LIBDIR)/pkgconfig/shadecalc.pc
	install -m 644 man/shadecalc.1 $(DESTDIR)$(PREFIX)/share/man/man1/shadecalc.1
	install -m 644 man/shadecalc.3 $(DESTDIR)$(PREFIX)/share/man/man3/shadecalc.3

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/shadecalc $(LIBDIR)/libshadecalc.a \
	    $(LIBDIR)/libshadecalc.so $(LIBDIR)/$(SONAME) $(LIBDIR)/libshadecalc.so.$(VERSION) \
	    $(LIBDIR)/pkgconfig/shadecalc.pc $(DESTDIR)$(PREFIX)/share/man/man1/shadecalc.1 \
	    $(DESTDIR)$(PREFIX)/share/man/man3/shadecalc.3
	rm -rf $(DESTDIR)$(PREFIX)/include/shadecalc

# The style is .clang-format's; format-check fails, naming each place, where a file departs from it.
FORMAT_FILES = $$(find src include tests bench -name '*.[ch]')
format:
	clang-format -i $(FORMAT_FILES)

.PHONY: format-check
format-check:
	@clang-format --dry-run -Werror $(FORMAT_FILES) && echo "format-check: the sources follow .clang-format"

clean:
	rm -rf build build-* 

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)

# ---- the LTC table (src/light/ltc_table.c, docs/ltc.md) -------------------------------------
# Not part of check: the fit takes minutes of one core. `make ltc-table` fits and rewrites the
# table, then measures the rebuilt library's table against brute force (`make ltc-error`).
LTC_FIT := $(BUILD)/tools/ltc_fit
$(LTC_FIT): $(BUILD)/obj/tools/ltc_fit.o $(STATIC)
	@mkdir -p $(dir $@)
	$(CC) $(LDALL) -o $@ $< $(STATIC) $(LDLIBS)

.PHONY: ltc-table ltc-error
ltc-table: $(LTC_FIT)
	$(LTC_FIT) table src/light/ltc_table.c
	@$(MAKE) --no-print-directory ltc-error

ltc-error: $(LTC_FIT)
	$(LTC_FIT) error
