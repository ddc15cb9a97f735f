# Exit status 1 is for runtime errors, 2 for usage errors (man page, EXIT STATUS), in every
# command: a runaway loop, an output that cannot be created or written, each with a message.
. tests/e2e/lib.sh

D=tests/brdf
RUNAWAY='float s = 0.0; while (s >= 0.0) s += 1.0; s'

# ---- a program that runs away, or fails at run time ----
expect "eval: runaway loop" 1 '' "~more than 1000 loop iterations" \
    -- eval --max-iterations 1000 "$RUNAWAY"
expect_stdin "eval --file: runaway loop" "$RUNAWAY" 1 '' "~more than 1000 loop iterations" \
    -- eval --max-iterations 1000 --file -
expect "eval --strict: domain error" 1 '' "~outside the GLSL ES domain (--strict)" \
    -- eval --strict 'sqrt(-1.0)'
expect "sweep: runaway loop in a row" 1 'x,value
0,0' "~sweep: row 2: column" \
    -- sweep --var x=0:1:3 "float s = x; while (s > 0.0) s += 1.0; s"
expect "sweep: index out of range in a row" 1 '*' "~sweep: row 3: column" \
    -- sweep --var x=0:1:3 'vec2 v = vec2(x); v[int(x * 2.0)]'
expect "sweep: runaway BRDF file" 1 '*' "~more than 100000 loop iterations" \
    -- sweep --brdf "file=$D/loop.brdf" --var theta_o=0:80:3
expect "sweep: runaway BRDF file, plot only" 1 '' "~more than 100000 loop iterations" \
    -- sweep --brdf "file=$D/loop.brdf" --var theta_o=0:80:3 --plot "$e2e_tmp/loop.svg"
# a spec that a row's values make invalid stays a usage error
expect "sweep: a row's spec invalid" 2 '*' "~sweep: row 2: 'lambert diff=-1'" \
    -- sweep --var d=1,-1 --brdf 'lambert diff=$d'

# ---- an output that cannot be created ----
missing=$e2e_tmp/missing
expect "sweep -o in a missing directory" 1 '' "~$missing/t.csv" \
    -- sweep --var x=0:1:3 -o "$missing/t.csv" x
expect "render -o in a missing directory" 1 '' "~$missing/r.exr" \
    -- render --size 8x8 -o "$missing/r.exr"
expect "brdf --export -o in a missing directory" 1 '' "~$missing/l.brdf" \
    -- brdf --export lambert -o "$missing/l.brdf"
verdict "nothing created" test ! -e "$missing"
echo >"$e2e_tmp/plain" # --compare creates its directory, but not below a regular file
expect "render --compare --output-dir below a file" 1 '' "~$e2e_tmp/plain" \
    -- render --compare --size 8x8 --output-dir "$e2e_tmp/plain/dir"

# ---- standard output on a full device (the commands tests/e2e/test_output.sh does not run) ----
if [ -w /dev/full ]; then
    full() { # WHAT ARGS...: exit 1 and the message, standard output on /dev/full
        what=$1; shift
        "$SHADECALC" "$@" </dev/null >/dev/full 2>"$e2e_tmp/err"
        status=$?
        verdict "$what: status 1 on /dev/full" test "$status" = 1
        verdict "$what: message on /dev/full" \
            grep -q '^error: standard output: No space left on device$' "$e2e_tmp/err"
    }
    full "brdf --export" brdf --export lambert
    full "normal --matrix" normal --matrix 'scale(1,2,3)'
    full "check, two BRDFs" check --brdf lambert --brdf 'phong m=10' --theta 0,60
    full "sweep --preset" sweep --preset spot
    full "shade --explain" shade --explain --light 'directional dir=0,0,1' --brdf lambert
    printf 'float x = 2.0;\nx * x;\nsqrt(x);\n' >"$e2e_tmp/p.glsl"
    full "eval --file" eval --file "$e2e_tmp/p.glsl"
fi
