# A write that fails on standard output (a full device) is an error, exit status 1, that names
# standard output and the reason, whether the table goes there by default or by -o -.
. tests/e2e/lib.sh

if [ -w /dev/full ]; then
    for out in default -; do
        set -- sweep 'x*x' --var x=0:1:3
        [ "$out" = - ] && set -- "$@" -o -
        "$SHADECALC" "$@" >/dev/full 2>"$e2e_tmp/err"
        status=$?
        verdict "full stdout ($out): status 1" test "$status" = 1
        verdict "full stdout ($out): message" grep -q '^error: standard output: No space left on device$' "$e2e_tmp/err"
    done
fi
