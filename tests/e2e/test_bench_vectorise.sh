# The peer rows of `shadecalc bench` are the plain loops of bench/libm_loops.c as a user who tried
# gets them with -ffast-math (issue 12): their element loops must vectorise, or the rows time a
# scalar loop no such user would keep. Each compiler installed builds bench/fastmath_CC.c with
# the Makefile's FASTMATH flags and reports, per loop, whether it vectorised (gcc
# -fopt-info-vec, clang -Rpass=loop-vectorize); the element loop of each function below must
# have vectorised in every copy (light_loop is inlined once per light kind and BRDF).
. tests/e2e/lib.sh

loops="light_loop brdf_arrays normalize_arrays fill3"
flags=$(sed -n 's/^FASTMATH ?= //p' Makefile)
cflags="-Iinclude -Isrc -I. -D_POSIX_C_SOURCE=200809L -std=c11 $flags"

# The line of the first element loop (for (size_t i ...) in function $1 of bench/libm_loops.c
loop_line() {
    awk -v f="$1" '$0 ~ "^static .*[ *]" f "\\(" { inside = 1 }
                   inside && /^ +for \(size_t i/ { print NR; exit }' bench/libm_loops.c
}

# remarks CC: the vectorisation remarks of CC on bench/fastmath_CC.c, one per line
# shellcheck disable=SC2086 # $cflags is a list of flags
remarks() {
    case $1 in
        gcc) gcc $cflags -fopt-info-vec-optimized -fopt-info-vec-missed -c bench/fastmath_gcc.c \
                 -o "$e2e_tmp/gcc.o" 2>&1 ;;
        clang) clang $cflags -Rpass=loop-vectorize -Rpass-missed=loop-vectorize \
                   -c bench/fastmath_clang.c -o "$e2e_tmp/clang.o" 2>&1 ;;
    esac
}

# vectorised CC F: F's element loop vectorised in every copy (a remark that it did, none that it
# did not); the remarks at its line printed otherwise
vectorised() {
    line=$(loop_line "$2")
    at="libm_loops.c:$line:"
    [ -n "$line" ] && grep -q "$at.*\(loop vectorized\|vectorized loop\)" "$e2e_tmp/$1.txt" &&
        ! grep -q "$at.*\(couldn't vectorize loop\|loop not vectorized\)" "$e2e_tmp/$1.txt" && return
    grep "$at" "$e2e_tmp/$1.txt" | sort -u | head -5
    return 1
}

for cc in gcc clang; do
    command -v $cc >/dev/null 2>&1 || continue
    remarks $cc >"$e2e_tmp/$cc.txt"
    for f in $loops; do
        verdict "$cc vectorises $f" vectorised $cc "$f"
    done
done
