# Where output goes (issue 11 §3, §4, §5, §8): standard output checked at exit, files that are
# not regular written into rather than replaced, links followed, read-only files refused,
# temporaries removed on signals, a failed allocation reported as a runtime error.
. tests/e2e/lib.sh

verdict() { # NAME OK DETAIL: one pass or fail, counted like expect's
    if [ "$2" = 1 ]; then
        echo "ok   $1"; echo pass >>"$E2E_COUNTS"
    else
        echo "FAIL $1: $3"; echo fail >>"$E2E_COUNTS"
    fi
}

d=$e2e_tmp/files
mkdir "$d"
temps() { ls -A "$1" | grep -c '\.tmp$'; } # temporaries left in directory $1

# ---- §3 standard output: a failed write is exit 1 with a message, whichever command ----

# Each line: one command that prints to standard output.
commands() {
    cat <<EOF
--help
--version
help
eval 1
eval --help
shade --light directional\ dir=0,0,1
shade --help
check --brdf lambert
normal --surface sphere --uv 0.3,0.3
bench --list
render --compare --size 16x16 --output-dir $d
render --help
sweep --var x=0:1:3 x
sweep --help
EOF
}

lost_output() { # NAME WANT_MESSAGE REDIRECTION: every command with stdout sent there
    what=$1 want=$2 where=$3
    commands | while IFS= read -r line; do
        # shellcheck disable=SC2086 # the line is the command's words
        case $where in
            full) eval "set -- $line"; "$SHADECALC" "$@" </dev/null >/dev/full 2>"$e2e_tmp/err" ;;
            closed) eval "set -- $line"; "$SHADECALC" "$@" </dev/null >&- 2>"$e2e_tmp/err" ;;
        esac
        status=$?
        err=$(cat "$e2e_tmp/err")
        [ "$status" = 1 ] && [ "$err" = "$want" ]
        verdict "$what: $line" $((! $?)) "status $status, stderr [$err]"
    done
}
lost_output "stdout /dev/full" "error: standard output: No space left on device" full
lost_output "stdout closed" "error: standard output: Bad file descriptor" closed

"$SHADECALC" eval $(seq 1 3000) 2>"$e2e_tmp/err" | head -1 >/dev/null
verdict "a reader that quits early (eval | head) is not reported" \
    "$([ ! -s "$e2e_tmp/err" ] && echo 1)" "stderr [$(cat "$e2e_tmp/err")]"
"$SHADECALC" sweep --var x=0:1:1000000 x 2>"$e2e_tmp/err" | head -1 >/dev/null
verdict "a reader that quits early (sweep | head) is not reported" \
    "$([ ! -s "$e2e_tmp/err" ] && echo 1)" "stderr [$(cat "$e2e_tmp/err")]"

# With stdout closed the first file opened would get descriptor 1: the table must still go to
# its file, and what goes to stdout must still fail.
"$SHADECALC" sweep --var x=0:1:3 -o "$d/closed.csv" x >&- 2>"$e2e_tmp/err"
verdict "stdout closed: -o FILE still gets the whole table" \
    "$([ $? = 0 ] && [ "$(cat "$d/closed.csv")" = "$(printf 'x,value\n0,0\n0.5,0.5\n1,1')" ] &&
        echo 1)" "$(cat "$d/closed.csv" "$e2e_tmp/err")"

"$SHADECALC" sweep --var x=0:1:3 -o /dev/null x >&- 2>"$e2e_tmp/err"
verdict "stdout closed: -o /dev/null is not taken for standard output" \
    "$([ $? = 0 ] && [ ! -s "$e2e_tmp/err" ] && echo 1)" "$(cat "$e2e_tmp/err")"

# ---- §4 what the writer replaces ----

table=$(printf 'x,value\n0,0\n1,1') # the table of --var x=0:1:2 x

"$SHADECALC" sweep --var x=0:1:2 -o /dev/null x
verdict "-o /dev/null: status 0, /dev/null still a character device" \
    "$([ $? = 0 ] && [ -c /dev/null ] && echo 1)" "$(ls -l /dev/null)"

if mknod "$d/full" c 1 7 2>/dev/null; then # a device of our own, never the system's /dev/full
    for opt in -o --plot --image --heatmap; do
        case $opt in
            -o) args="--var x=0:1:2 -o $d/full x" ;;
            --plot) args="--var x=0:1:2 --plot $d/full x" ;;
            --image) args="--var x=0:1:2 --var y=0:1:2 --image $d/full x*y" ;;
            --heatmap) args="--var x=0:1:2 --var y=0:1:2 --heatmap $d/full x*y" ;;
        esac
        # shellcheck disable=SC2086
        "$SHADECALC" sweep $args 2>"$e2e_tmp/err"
        status=$?
        err=$(cat "$e2e_tmp/err")
        [ $status = 1 ] && [ -c "$d/full" ] &&
            [ "$err" = "error: $d/full: No space left on device" ]
        verdict "sweep $opt DEVICE is written into (ENOSPC), not replaced" $((! $?)) \
            "status $status, [$err], $(ls -l "$d/full")"
    done
    "$SHADECALC" render --size 8x8 -o "$d/full" 2>"$e2e_tmp/err"
    verdict "render -o DEVICE is written into, not replaced" \
        "$([ $? = 1 ] && [ -c "$d/full" ] && echo 1)" "$(cat "$e2e_tmp/err")"
else
    echo "skip device nodes (mknod needs root)"
fi

echo old >"$d/real.csv"
ln -s real.csv "$d/link.csv"
mkdir "$d/sub"
ln -s ../link.csv "$d/sub/chain.csv"
"$SHADECALC" sweep --var x=0:1:2 -o "$d/sub/chain.csv" x
verdict "-o through a chain of symbolic links replaces the file they end at" \
    "$([ -L "$d/link.csv" ] && [ -L "$d/sub/chain.csv" ] && [ "$(cat "$d/real.csv")" = "$table" ] &&
        [ "$(temps "$d")$(temps "$d/sub")" = 00 ] && echo 1)" "$(ls -lA "$d" "$d/sub")"

ln -s new.csv "$d/dangling.csv"
"$SHADECALC" sweep --var x=0:1:2 -o "$d/dangling.csv" x
verdict "-o a dangling link creates its target" \
    "$([ -L "$d/dangling.csv" ] && [ "$(cat "$d/new.csv")" = "$table" ] && echo 1)" \
    "$(ls -lA "$d")"

mkfifo "$d/fifo"
timeout 20 cat "$d/fifo" >"$d/from_fifo" & # a replaced FIFO would leave it waiting
reader=$!
"$SHADECALC" sweep --var x=0:1:2 -o "$d/fifo" x
status=$?
wait $reader
verdict "-o FIFO: the reader gets the table, the FIFO stays" \
    "$([ $status = 0 ] && [ -p "$d/fifo" ] && [ "$(cat "$d/from_fifo")" = "$table" ] && echo 1)" \
    "status $status, got [$(cat "$d/from_fifo")]"

echo kept >"$d/append.csv"
"$SHADECALC" sweep --var x=0:1:2 -o /dev/stdout x >>"$d/append.csv"
verdict "-o /dev/stdout writes to standard output (appended, not replaced)" \
    "$([ "$(cat "$d/append.csv")" = "$(printf 'kept\n%s' "$table")" ] && echo 1)" \
    "$(cat "$d/append.csv")"

echo old >"$d/mode.csv"
chmod 640 "$d/mode.csv"
"$SHADECALC" sweep --var x=0:1:2 -o "$d/mode.csv" x
verdict "a replaced file keeps its mode" \
    "$([ "$(stat -c %a "$d/mode.csv")" = 640 ] && [ "$(cat "$d/mode.csv")" = "$table" ] && echo 1)" \
    "$(stat -c %a "$d/mode.csv")"

if [ "$(id -u)" = 0 ]; then
    echo old >"$d/owned.csv"
    chown 65534:65534 "$d/owned.csv"
    "$SHADECALC" sweep --var x=0:1:2 -o "$d/owned.csv" x
    verdict "as root, a replaced file keeps its owner and group" \
        "$([ "$(stat -c %u:%g "$d/owned.csv")" = 65534:65534 ] && echo 1)" \
        "$(stat -c %u:%g "$d/owned.csv")"
fi

echo read-only >"$d/ro.csv"
chmod 444 "$d/ro.csv"
expect "-o a read-only file is refused" 1 '' \
    "error: $d/ro.csv: read-only file, not replaced (--force replaces it)" \
    -- sweep --var x=0:1:2 -o "$d/ro.csv" x
expect "--image a read-only file is refused" 1 '' \
    "error: $d/ro.csv: read-only file, not replaced (--force replaces it)" \
    -- sweep --var x=0:1:2 --var y=0:1:2 --image "$d/ro.csv" 'x*y'
expect "render -o a read-only file is refused" 1 '' \
    "error: $d/ro.csv: read-only file, not replaced (--force replaces it)" \
    -- render --size 8x8 -o "$d/ro.csv"
verdict "the refused read-only file is untouched" \
    "$([ "$(cat "$d/ro.csv")" = read-only ] && [ "$(temps "$d")" = 0 ] && echo 1)" \
    "$(cat "$d/ro.csv")"
"$SHADECALC" sweep --force --var x=0:1:2 -o "$d/ro.csv" x
verdict "--force replaces a read-only file, which stays read-only" \
    "$([ "$(cat "$d/ro.csv")" = "$table" ] && [ "$(stat -c %a "$d/ro.csv")" = 444 ] && echo 1)" \
    "$(stat -c %a "$d/ro.csv"): $(cat "$d/ro.csv")"
"$SHADECALC" render --force --size 8x8 -o "$d/ro.csv"
verdict "render --force replaces a read-only file" \
    "$([ $? = 0 ] && [ "$(head -c 4 "$d/ro.csv" | od -An -tx1 | tr -d ' ')" = 762f3101 ] && echo 1)" \
    "$(head -c 4 "$d/ro.csv" | od -An -tx1)"

# ---- §5 signals: the temporary is removed, the old file kept, status 128 + signal ----

interrupted() { # NAME SIGNAL STATUS [RUNNER...]: a long sweep -o killed once its temporary exists
    name=$1 sig=$2 want=$3
    shift 3
    echo old >"$d/long.csv"
    "$@" "$SHADECALC" sweep -j 4 --var x=0:1:100000000 -o "$d/long.csv" 'sin(x)' 2>/dev/null &
    pid=$!
    for _ in $(seq 100); do [ "$(temps "$d")" = 1 ] && break; sleep 0.1; done
    created=$(temps "$d")
    kill -"$sig" $pid
    wait $pid 2>/dev/null
    status=$?
    [ "$created" = 1 ] && [ "$status" = "$want" ] && [ "$(temps "$d")" = 0 ] &&
        [ "$(cat "$d/long.csv")" = old ]
    verdict "$name" $((! $?)) "temporary seen: $created, status $status, left: $(ls -A "$d")"
}
# Each run restores the signal's default action first where env can (a background job starts
# with SIGINT ignored, a run under nohup with SIGHUP ignored, and an ignored signal rightly
# stays ignored in shadecalc).
if env --default-signal=INT true 2>/dev/null; then
    interrupted "SIGTERM during sweep -o: temporary removed, old file kept, status 143" TERM 143 \
        env --default-signal=TERM
    interrupted "SIGHUP during sweep -o: temporary removed, status 129" HUP 129 \
        env --default-signal=HUP
    interrupted "SIGINT during sweep -o: temporary removed, status 130" INT 130 \
        env --default-signal=INT
else
    interrupted "SIGTERM during sweep -o: temporary removed, old file kept, status 143" TERM 143
    interrupted "SIGHUP during sweep -o: temporary removed, status 129" HUP 129
fi

(
    ulimit -f 64
    "$SHADECALC" sweep --var x=0:1:1000000 -o "$d/limited.csv" x 2>"$e2e_tmp/err"
)
verdict "past ulimit -f: 'File too large', exit 1, no temporary" \
    "$([ $? = 1 ] && [ "$(temps "$d")" = 0 ] && grep -q 'File too large' "$e2e_tmp/err" && echo 1)" \
    "$(cat "$e2e_tmp/err"; ls -A "$d")"

# ---- §8 a failed allocation is a runtime error (1), not a usage error ----

limit=150000 # KiB of address space: shadecalc starts, 256 MB of pixels do not fit
if (ulimit -v $limit && "$SHADECALC" --version >/dev/null 2>&1); then # not under ASan
    (
        ulimit -v $limit
        "$SHADECALC" sweep --var x=0:1:8000 --var y=0:1:8000 --image "$d/big.exr" 'x*y'
    ) >"$e2e_tmp/out" 2>"$e2e_tmp/err"
    verdict "sweep --image 8000x8000 under ulimit -v: out of memory, exit 1" \
        "$([ $? = 1 ] && grep -q 'out of memory' "$e2e_tmp/err" && echo 1)" "$(cat "$e2e_tmp/err")"
    (
        ulimit -v $limit
        "$SHADECALC" render --size 16384x2048 -o "$d/big.exr"
    ) >"$e2e_tmp/out" 2>"$e2e_tmp/err"
    verdict "render 16384x2048 under ulimit -v: out of memory, exit 1" \
        "$([ $? = 1 ] && grep -q 'out of memory' "$e2e_tmp/err" && echo 1)" "$(cat "$e2e_tmp/err")"
else
    echo "skip ulimit -v (the binary does not start under it: a sanitizer build)"
fi
