#!/bin/sh
# The library's interface against its headers (`make lib-tests`). Usage: exports.sh BUILD CC
#  - every header of include/shadecalc/ compiles alone, as C11 with CC and as C++11 with g++
#    and clang++ (those installed), with -Wall -Wextra -Wpedantic -Werror;
#  - shadecalc/shadecalc.h includes every header;
#  - the functions the headers declare (as gcc itself lists them, -aux-info) are exactly the
#    functions libshadecalc.so exports (nm -D --defined-only), and the variables declared
#    `extern` exactly the data it exports: both directions, each difference named;
#  - a C program and a C++ program that take the address of every declared function and
#    variable link against libshadecalc.so (C++: every declaration has C linkage); the C one
#    also keeps every static inline function of the headers (-fkeep-inline-functions), so an
#    inline function calling an internal function fails here;
#  - man/shadecalc.3's accuracy table lists sc_accuracy_table's rows;
#  - the shared library's file name and soname, and both manual pages' headers, carry the
#    version of shadecalc/version.h.
set -u
BUILD=$1 CC=$2
TEST=exports
. tests/install/lib.sh
so=$BUILD/libshadecalc.so
strict="$strict -Iinclude"

# ---- each header alone, in C and in C++ ----
for h in include/shadecalc/*.h; do
    name=${h#include/}
    printf '#include "%s"\ntypedef int one_header;\n' "$name" >"$tmp/one.c"
    # shellcheck disable=SC2086
    $CC -std=c11 $strict -fsyntax-only "$tmp/one.c" 2>"$tmp/err" || fail "$name in C: $(head -3 "$tmp/err")"
    for cxx in $cxx_compilers; do
        # shellcheck disable=SC2086
        $cxx -x c++ -std=c++11 $strict -fsyntax-only "$tmp/one.c" 2>"$tmp/err" ||
            fail "$name in C++ ($cxx): $(head -3 "$tmp/err")"
    done
done

# ---- the umbrella header ----
$CC -Iinclude -MM include/shadecalc/shadecalc.h | tr ' \\' '\n\n' | grep '^include/' | sort -u >"$tmp/umbrella"
for h in include/shadecalc/*.h; do
    grep -qx "$h" "$tmp/umbrella" || fail "shadecalc/shadecalc.h does not include $h"
done

# ---- declared against exported ----
if ! command -v gcc >/dev/null; then
    finish "headers alone; gcc not found: the symbol comparison needs its -aux-info, skipped"
fi
echo '#include "shadecalc/shadecalc.h"' >"$tmp/all.c"
gcc -std=c11 -Iinclude -fsyntax-only -aux-info "$tmp/aux" "$tmp/all.c" || fail "gcc -aux-info"
# Lines "/* include/shadecalc/H:LINE:NC */ extern TYPE NAME (PARAMS);" — NC: not static.
grep '^/\* include/shadecalc/[^ ]*:NC \*/ extern ' "$tmp/aux" |
    sed 's/^[^(]*[^A-Za-z0-9_(]\([A-Za-z_][A-Za-z0-9_]*\) (.*/\1/' | sort -u >"$tmp/declared.fn"
grep -h '^extern .*;' include/shadecalc/*.h |
    sed 's/^.*[^A-Za-z0-9_]\([A-Za-z_][A-Za-z0-9_]*\)\(\[[^]]*\]\)* *;.*/\1/' | sort -u >"$tmp/declared.data"
nm -D --defined-only "$so" >"$tmp/nm" || fail "nm -D $so"
awk '$2 ~ /^[TWi]$/ {print $3}' "$tmp/nm" | sort -u >"$tmp/exported.fn"
awk '$2 !~ /^[TWi]$/ {print $3}' "$tmp/nm" | sort -u >"$tmp/exported.data"
compare() { # KIND
    comm -23 "$tmp/declared.$1" "$tmp/exported.$1" >"$tmp/missing"
    comm -13 "$tmp/declared.$1" "$tmp/exported.$1" >"$tmp/extra"
    [ -s "$tmp/missing" ] && fail "declared in a header, not exported ($1):" $(cat "$tmp/missing")
    [ -s "$tmp/extra" ] && fail "exported, declared in no header ($1):" $(cat "$tmp/extra")
}
compare fn
compare data
[ "$(wc -l <"$tmp/declared.fn")" -gt 100 ] || fail "only $(wc -l <"$tmp/declared.fn") functions found in the headers"

# ---- every declaration linked, from C and from C++ ----
{
    echo '#include "shadecalc/shadecalc.h"'
    echo 'typedef void (*any_function)(void);'
    echo 'static const any_function functions[] = {'
    sed 's/.*/    (any_function)\&&,/' "$tmp/declared.fn"
    echo '};'
    echo 'static const void *const data[] = {'
    sed 's/.*/    (const void *)\&&,/' "$tmp/declared.data"
    echo '};'
    echo 'int main(void) { return functions[0] == 0 || data[0] == 0; }'
} >"$tmp/link.c"
libs="-L$BUILD -lshadecalc -lm"
# shellcheck disable=SC2086
gcc -std=c11 $strict -fkeep-inline-functions "$tmp/link.c" -o "$tmp/link-c" $libs 2>"$tmp/err" ||
    fail "linking every declaration from C: $(grep -m3 -e error -e undefined "$tmp/err")"
for cxx in $cxx_compilers; do
    # shellcheck disable=SC2086
    $cxx -x c++ -std=c++11 $strict "$tmp/link.c" -o "$tmp/link-cxx" $libs 2>"$tmp/err" ||
        fail "linking every declaration from C++ ($cxx): $(grep -m3 -e error -e undefined "$tmp/err")"
done

# ---- the man page's accuracy table is sc_accuracy_table ----
cat >"$tmp/table.c" <<'EOF'
#include <stdio.h>
#include "shadecalc/accuracy.h"
int main(void) {
    for (int i = 0; i < sc_accuracy_count; i++) {
        const sc_accuracy_row *r = &sc_accuracy_table[i];
        printf(".TP\n.B %s\n%s: %g ULP\n", r->name, r->domain, r->bound_ulp);
    }
    return 0;
}
EOF
# shellcheck disable=SC2086
if $CC -std=c11 $strict "$tmp/table.c" -o "$tmp/table" $libs 2>"$tmp/err"; then
    LD_LIBRARY_PATH=$BUILD "$tmp/table" >"$tmp/table.want"
    sed -n '/BEGIN accuracy table/,/END accuracy table/p' man/shadecalc.3 | sed '1d;$d' >"$tmp/table.man"
    cmp -s "$tmp/table.want" "$tmp/table.man" ||
        fail "man/shadecalc.3's accuracy table is not sc_accuracy_table: $(diff "$tmp/table.man" "$tmp/table.want")"
else fail "accuracy table program: $(head -3 "$tmp/err")"; fi

# ---- the version in the library's names ----
major=$(sed -n 's/^#define SC_VERSION_MAJOR *//p' include/shadecalc/version.h)
version=$major.$(sed -n 's/^#define SC_VERSION_MINOR *//p' include/shadecalc/version.h).$(sed -n 's/^#define SC_VERSION_PATCH *//p' include/shadecalc/version.h)
[ -f "$BUILD/libshadecalc.so.$version" ] || fail "no $BUILD/libshadecalc.so.$version (version.h says $version)"
soname=$(readelf -d "$so" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[ "$soname" = "libshadecalc.so.$major" ] || fail "soname '$soname', want libshadecalc.so.$major"
for page in man/shadecalc.1 man/shadecalc.3; do
    grep -q "^\.TH .* \"shadecalc $version\"" "$page" || fail "$page: its .TH line does not say shadecalc $version"
done

finish "$(wc -l <"$tmp/exported.fn") functions and $(wc -l <"$tmp/exported.data") variables exported, as declared"
