# Command-line conventions shared by every subcommand (man page: CONVENTIONS): options anywhere,
# '--', negative numbers as operands, '-' for standard input and output, did-you-mean.
. tests/e2e/lib.sh
t=$e2e_tmp

# Options after operands. 1/3 in binary16 is 0x3555 = 0.33325195..., shortest decimal 0.3333.
expect "eval: option after the operand"   0 '0.3333' '' -- eval '1.0/3.0' --precision mediump
expect "eval: option between operands"    0 '1
0.5' '' -- eval 1 -p lowp 0.5
expect "sweep: -o after EXPR"             0 '' '' -- sweep --var x=0:1:3 'x*2.0' -o "$t/trailing.csv"
expect "sweep: the table written"         0 'x,value
0,0
0.5,1
1,2' '' -- sweep --var x=0:1:3 'x*2.0'
expect "sweep: --var after EXPR"          0 '~0.5,1' '' -- sweep 'x*2.0' --var x=0:1:3
expect "normal: options after --triangle" 0 'nx,ny,nz,area,degenerate
0,0,1,0.5,0' '' -- normal --triangle 0,0,0 1,0,0 0,1,0 -f csv
expect "normal: -f before the last points" 0 'nx,ny,nz,area,degenerate
0,0,1,0.5,0' '' -- normal --triangle 0,0,0 -f csv 1,0,0 0,1,0

# '--' ends the options.
expect "eval: -- then a negative number"  0 '-1' '' -- eval -- -1
expect "eval: -- then an option's name"   2 '' "~'precision' is not a variable" -- eval -- 1 --precision
expect "sweep: -- keeps -o an operand"    2 '' "~unexpected argument '-o'" -- sweep --var x=0:1:2 x -- -o

# Negative numbers and expressions are operands: '-' then a digit, '.' or '('.
expect "eval -1.0"                        0 '-1' '' -- eval -1.0
expect "eval -.5"                         0 '-0.5' '' -- eval -.5
expect "eval '-(1.0)'"                    0 '-1' '' -- eval '-(1.0)'
expect "eval -p highp -0.001"             0 '-0.001' '' -- eval -p highp '-0.001'
expect "eval -2.0*3.0 after -p"           0 '-6' '' -- eval -p double '-2.0*3.0'
expect "an option value may be negative"  0 '~-1,-1' '' -- sweep --var x=-1,1 x
expect "normal: negative triangle points" 0 '~0,0,1,0.5' '' -- normal -f csv --triangle 0,0,0 -1,0,0 0,-1,0

# Unknown options: the closest long option, or the hint at '--'.
expect "did you mean --precision"         2 '' "error: eval: unknown option '--precison'; did you mean '--precision'? (see 'shadecalc eval --help')" -- eval --precison lowp 1
expect "did you mean --output"            2 '' "~did you mean '--output'?" -- sweep --var x=0:1:2 x --ouput f.csv
expect "an unknown short option hints --" 2 '' "~unknown option '-z'; an operand that starts with '-' goes after '--'" -- eval -z
expect "a missing value"                  2 '' "error: eval: option '--precision' needs a value (see 'shadecalc eval --help')" -- eval 1 --precision
expect "a missing short value"            2 '' "error: render: option '-o' needs a value (see 'shadecalc render --help')" -- render -o

# Output formats: one name for JSON Lines, an expression column in eval's CSV, one rule for
# result columns named like variables, the same keys in shade's JSON as in its text.
expect "eval -f jsonl"                    0 '{"expression": "1.5", "precision": "highp", "type": "float", "value": 1.5}' '' -- eval -f jsonl 1.5
expect "sweep -f json is JSON Lines"      0 '{"x": 2, "value": 4}' '' -- sweep -f json --var x=2 'x*x'
expect "eval csv: an expression column"   0 'expression,value
1.0/4.0,0.25
"max(1.0, 2.0)",2' '' -- eval -f csv '1.0/4.0' 'max(1.0, 2.0)'
expect "eval csv: a newline is quoted"    0 'expression,value
"1.0 +
1.0",2' '' -- eval -f csv "$(printf '1.0 +\n1.0')"
expect "sweep: every result renamed"      0 '~r,result_r,result_g,result_b' '' -- sweep --var r=1 --light 'point pos=0,0,$r'
expect "sweep: no clash, no rename"       0 '~q,r,g,b' '' -- sweep --var q=1 --light 'point pos=0,0,$q'
# cos θ_o of v = (0,1,1)/√2 about n = (0,1,0) is √½, 0.70710677 in binary32.
expect "shade json explain: cos_theta_o"  0 '~"cos_theta_i": 1, "cos_theta_o": 0.70710677, "cos_theta_h": 0.9238795' '' -- shade -f json --explain -l 'spot pos=0,4,0 dir=0,-1,0 spot=directx inner=20 outer=30' -b ward --n 0,1,0 --v 0,1,1
expect "shade json explain: cos_theta_s"  0 '~"spot": 1, "cos_theta_s": 1' '' -- shade -f json --explain -l 'spot pos=0,4,0 dir=0,-1,0 spot=directx inner=20 outer=30' -b ward --n 0,1,0 --v 0,1,1
expect "shade json explain: ward exp_term" 0 '~"exp_term": ' '' -- shade -f json --explain -l 'spot pos=0,4,0 dir=0,-1,0 spot=directx inner=20 outer=30' -b ward --n 0,1,0 --v 0,1,1
expect "shade json explain: primary"      0 '~"primary": [' '' -- shade -f json --explain -l "directional dir=0,0,1" -b 'opengl separate-specular=1'

# Progress bars (standard error on a terminal, from script(1)): at most ~10 redraws a second,
# with an ETA. 27 million rows of three built-ins on one thread run for a few seconds (9 million,
# since the scalar kernels run in vector lanes, take about 1.5 s: too close to the bar's
# one-second delay on a loaded machine).
if command -v script >/dev/null 2>&1; then
    start=$(date +%s.%N)
    script -qec "'$SHADECALC' sweep -j 1 --var x=0:1:9000 --var y=0:1:3000 --image '$t/progress.exr' 'sin(x * 7.0) * cos(y * 5.0) + pow(x, y)'" /dev/null >"$t/tty.out" 2>&1
    end=$(date +%s.%N)
    redraws=$(tr '\r' '\n' <"$t/tty.out" | grep -c '^sweep \[')
    if awk -v n="$redraws" -v s="$start" -v e="$end" 'BEGIN { exit !(n <= 10 * (e - s) + 3) }' &&
        grep -q 'ETA [0-9]' "$t/tty.out"; then
        echo "ok   progress: $redraws redraws, with an ETA"; echo pass >>"$E2E_COUNTS"
    else
        echo "FAIL progress: $redraws redraws in $start..$end, or no ETA"; echo fail >>"$E2E_COUNTS"
    fi
fi

# '-' is standard input or output wherever a file is named.
scene='light directional dir=0,0,1
brdf lambert'
expect_stdin "sweep -s -"                 "$scene" 0 'theta_i,r,g,b
0,0.25464790894703254,0.25464790894703254,0.25464790894703254' '' -- sweep -p double -s - --var theta_i=0
expect_stdin "render -s - -o -"           "$scene" 0 '*' '' -- render -s - --size 4x4 -o -
expect "sweep -o -"                       0 'x,value
1,1' '' -- sweep -o - --var x=1 x
# An EXR on standard output starts with the magic number 76 2f 31 01.
magic=$("$SHADECALC" render --size 4x4 -o - | od -An -tx1 -N4 | tr -d ' ')
[ "$magic" = 762f3101 ] && { echo "ok   render -o - writes the EXR"; echo pass >>"$E2E_COUNTS"; } ||
    { echo "FAIL render -o - writes the EXR: magic $magic"; echo fail >>"$E2E_COUNTS"; }
magic=$("$SHADECALC" sweep --var x=0,1 --var y=0,1 'x+y' --image - | od -An -tx1 -N4 | tr -d ' ')
[ "$magic" = 762f3101 ] && { echo "ok   sweep --image - writes the EXR"; echo pass >>"$E2E_COUNTS"; } ||
    { echo "FAIL sweep --image - writes the EXR: magic $magic"; echo fail >>"$E2E_COUNTS"; }
