# Sourced by tests/e2e/test_*.sh. $SHADECALC is the binary under test.
#
#   expect NAME STATUS STDOUT STDERR -- ARGS...
#       runs `shadecalc ARGS...` with no standard input and checks the exit status, the whole
#       standard output and the whole standard error (trailing newlines ignored).
#       STDOUT or STDERR given as '*' is not checked; '~TEXT' checks that it contains TEXT.
#   expect_stdin NAME INPUT STATUS STDOUT STDERR -- ARGS...   the same, with INPUT on stdin.
#   verdict NAME CONDITION...   a pass or a fail for a shell test.
#
# Each check prints 'ok NAME' or 'FAIL NAME' with a diff; the counts go to $E2E_COUNTS.

e2e_tmp=$(mktemp -d)
trap 'rm -rf "$e2e_tmp"' EXIT

e2e_match() { # WHAT EXPECTED ACTUAL
    case $2 in
        '*') return 0 ;;
        '~'*) case $3 in *"${2#\~}"*) return 0 ;; esac; return 1 ;;
        *) [ "$2" = "$3" ] ;;
    esac
}

e2e_run() { # NAME INPUT STATUS STDOUT STDERR -- ARGS...
    name=$1 input=$2 want_status=$3 want_out=$4 want_err=$5
    shift 6
    printf '%s' "$input" | "$SHADECALC" "$@" >"$e2e_tmp/out" 2>"$e2e_tmp/err"
    status=$?
    out=$(cat "$e2e_tmp/out"); err=$(cat "$e2e_tmp/err")
    ok=1
    [ "$status" = "$want_status" ] || ok=0
    e2e_match stdout "$want_out" "$out" || ok=0
    e2e_match stderr "$want_err" "$err" || ok=0
    if [ $ok = 1 ]; then
        echo "ok   $name"; echo pass >>"$E2E_COUNTS"
    else
        echo "FAIL $name: shadecalc $*"
        echo "  status: want $want_status, got $status"
        echo "  stdout: want [$want_out]"; echo "          got  [$out]"
        echo "  stderr: want [$want_err]"; echo "          got  [$err]"
        echo fail >>"$E2E_COUNTS"
    fi
}

verdict() {
    name=$1; shift
    if "$@"; then echo "ok   $name"; echo pass >>"$E2E_COUNTS"
    else echo "FAIL $name: $*"; echo fail >>"$E2E_COUNTS"; fi
}

expect() { n=$1; shift; e2e_run "$n" "" "$@"; }
expect_stdin() { n=$1 i=$2; shift 2; e2e_run "$n" "$i" "$@"; }

# expect_close NAME TOL 'X Y Z ...' -- ARGS...
#   runs `shadecalc ARGS...`, expects status 0 and whitespace- or comma-separated numbers on
#   standard output, each within relative tolerance TOL of the expected one (reference values).
expect_close() {
    name=$1 tol=$2 want=$3
    shift 4
    out=$("$SHADECALC" "$@" 2>"$e2e_tmp/err")
    status=$?
    if [ $status = 0 ] && printf '%s\n%s\n' "$want" "$out" | tr ',' ' ' | awk -v tol="$tol" '
        NR == 1 { n = split($0, w, " ") }
        NR == 2 { m = split($0, g, " ") }
        END {
            if (n != m) exit 1
            for (i = 1; i <= n; i++) {
                d = g[i] - w[i]; if (d < 0) d = -d
                a = w[i]; if (a < 0) a = -a
                if (d > tol * a) exit 1
            }
        }'; then
        echo "ok   $name"; echo pass >>"$E2E_COUNTS"
    else
        echo "FAIL $name: shadecalc $*"
        echo "  want [$want] within $tol, got [$out] (status $status)"
        echo fail >>"$E2E_COUNTS"
    fi
}

# verdict NAME CONDITION...: a pass or a fail for a shell test
verdict() {
    name=$1; shift
    if "$@"; then echo "ok   $name"; echo pass >>"$E2E_COUNTS"
    else echo "FAIL $name: $*"; echo fail >>"$E2E_COUNTS"; fi
}
