#!/bin/sh
# shadecalc as a user installs it (`make lib-tests`). Usage: run.sh MAKE CC
#  - `make install PREFIX=<temporary>`; tests/install/user.c built with nothing but the flags
#    of `pkg-config --cflags --libs shadecalc`, as C with CC and as C++ with g++ and clang++
#    (those installed), run against the installed shared library: every check it prints passes
#    and its version is pkg-config's and `shadecalc --version`'s;
#  - the same program linked with the installed static library and `pkg-config --static`'s
#    libraries (Libs.private);
#  - the EXAMPLE of shadecalc(3) builds the same way and prints 1/pi;
#  - shadecalc(1) and shadecalc(3) found by man under the prefix, without groff warnings;
#  - `make uninstall` leaves no file behind;
#  - `make install DESTDIR=<stage>` puts the same files under the stage, and nothing else.
set -u
MAKE=$1 CC=$2
TEST=install
. tests/install/lib.sh
make_quietly() { # ARGS...: fails the test with make's output if make fails
    $MAKE --no-print-directory CC="$CC" "$@" >"$tmp/make.log" 2>&1 && return 0
    cat "$tmp/make.log"
    fail "make $*"
    return 1
}
files_under() { # DIR: every file and symlink below DIR, relative, sorted
    (cd "$1" && find . ! -type d | sort)
}

prefix=$tmp/prefix
make_quietly install PREFIX="$prefix" || exit 1
PKG_CONFIG_PATH=$prefix/lib/pkgconfig
export PKG_CONFIG_PATH
version=$(pkg-config --modversion shadecalc) || fail "pkg-config does not find shadecalc.pc"
cflags=$(pkg-config --cflags shadecalc)
libs=$(pkg-config --libs shadecalc)
static_libs=$(pkg-config --static --libs shadecalc | sed "s|-lshadecalc|$prefix/lib/libshadecalc.a|")

run_user() { # NAME: runs the built program, checks what it printed
    LD_LIBRARY_PATH=$prefix/lib "$tmp/$1" >"$tmp/$1.out" 2>&1 || fail "$1 exits $?: $(grep -v '^ok ' "$tmp/$1.out")"
    grep -qx "version $version (header $version, .*)" "$tmp/$1.out" ||
        fail "$1: version line '$(head -1 "$tmp/$1.out")', pkg-config says $version"
    [ "$(grep -c '^ok ' "$tmp/$1.out")" -eq 6 ] || fail "$1: not 6 checks passed: $(cat "$tmp/$1.out")"
}
needs_shared() { # NAME YES|NO: whether the program loads libshadecalc.so
    if readelf -d "$tmp/$1" | grep -q 'NEEDED.*libshadecalc\.so'; then got=yes; else got=no; fi
    [ "$got" = "$2" ] || fail "$1: loads libshadecalc.so: $got, want $2"
}

# shellcheck disable=SC2086
if $CC -std=c11 $strict $cflags tests/install/user.c -o "$tmp/user-c" $libs -lm 2>"$tmp/err"; then
    needs_shared user-c yes
    run_user user-c
else fail "C build with pkg-config's flags: $(head -5 "$tmp/err")"; fi
for cxx in $cxx_compilers; do
    # shellcheck disable=SC2086
    if $cxx -x c++ -std=c++11 $strict $cflags tests/install/user.c -o "$tmp/user-$cxx" $libs 2>"$tmp/err"; then
        run_user "user-$cxx"
    else fail "C++ build ($cxx) with pkg-config's flags: $(head -5 "$tmp/err")"; fi
done
# shellcheck disable=SC2086
if $CC -std=c11 $strict $cflags tests/install/user.c -o "$tmp/user-static" $static_libs 2>"$tmp/err"; then
    needs_shared user-static no
    run_user user-static
else fail "static link with pkg-config --static: $(head -5 "$tmp/err")"; fi

# The manual's EXAMPLE, as printed (roff's \e is a backslash).
sed -n '/^\.SH EXAMPLE/,/^\.SH/p' man/shadecalc.3 | sed -n '/^\.EX/,/^\.EE/p' | sed '1d;$d;s/\\e/\\/g' >"$tmp/example.c"
# shellcheck disable=SC2086
if $CC -std=c11 $strict $cflags "$tmp/example.c" -o "$tmp/example" $libs 2>"$tmp/err"; then
    LD_LIBRARY_PATH=$prefix/lib "$tmp/example" >"$tmp/example.out" 2>&1 || fail "man page example exits $?"
    grep -qx "shadecalc $version: L_o = 0.318310 (1/pi = 0.318310)" "$tmp/example.out" ||
        fail "man page example printed: $(cat "$tmp/example.out")"
else fail "man page example does not build: $(head -5 "$tmp/err")"; fi

cli_version=$("$prefix/bin/shadecalc" --version)
[ "$cli_version" = "shadecalc $version" ] || fail "shadecalc --version says '$cli_version', pkg-config $version"
man_pages=$(command -v man >/dev/null && command -v groff >/dev/null && echo 1 3)
[ -n "$man_pages" ] || echo "install: man or groff missing: the manual pages are not checked"
for page in $man_pages; do
    found=$(MANPATH=$prefix/share/man man -w "$page" shadecalc 2>/dev/null)
    [ "$found" = "$prefix/share/man/man$page/shadecalc.$page" ] || fail "man -w $page shadecalc: '$found'"
    warnings=$(groff -man -Tutf8 -ww -z "$prefix/share/man/man$page/shadecalc.$page" 2>&1)
    [ -z "$warnings" ] || fail "shadecalc($page): groff: $warnings"
done

files_under "$prefix" >"$tmp/installed"
make_quietly uninstall PREFIX="$prefix"
left=$(files_under "$prefix")
[ -z "$left" ] || fail "make uninstall left: $left"

stage=$tmp/stage
make_quietly install DESTDIR="$stage" PREFIX=/usr/local
files_under "$stage/usr/local" | cmp -s - "$tmp/installed" ||
    fail "DESTDIR install differs from the PREFIX one: $(files_under "$stage/usr/local" | diff - "$tmp/installed")"
[ "$(files_under "$stage" | grep -cv '^\./usr/local/')" -eq 0 ] || fail "DESTDIR install wrote outside PREFIX"
grep -qx 'prefix=/usr/local' "$stage/usr/local/lib/pkgconfig/shadecalc.pc" || fail "DESTDIR in shadecalc.pc"
make_quietly uninstall DESTDIR="$stage" PREFIX=/usr/local
[ -z "$(files_under "$stage")" ] || fail "make uninstall DESTDIR= left: $(files_under "$stage")"

finish "$(wc -l <"$tmp/installed") files installed and removed; C, C++, static"
