# shadecalc eval: the examples of the issue and the man page, every output format, errors.
. tests/e2e/lib.sh

expect "normalize example"        0 'vec3(0.6, 0, 0.8)' '' -- eval 'normalize(vec3(3,0,4))'
expect "dot type error"           2 '' 'error: column 1: dot: arguments vec3 and vec2 must have the same type' -- eval 'dot(vec3(1), vec2(1))'
expect "several expressions"      0 '0.5
vec2(1, 2)' '' -- eval '0.25 * 2.0' 'vec2(1,2)'
expect "statements"               0 'vec2(5, 8)' '' -- eval 'vec4 a = vec4(1,2,3,4); vec2 b = a.xy * 2.; b + a.zw'
# GLSL ES converts nothing implicitly: an int beside a float is an error that says what to write
expect "int beside float"         2 '' "error: column 5: operator '+': operands float and int do not match (GLSL ES converts nothing implicitly: write a float literal (1.0, not 1) or convert (float(...)))" -- eval '1.0 + 1'
expect "int argument of pow"      2 '' "~pow: argument 2 is int, and there is no such overload (GLSL ES converts nothing implicitly: write a float literal (1.0, not 1) or convert (float(...)))" -- eval 'pow(2.0, 3)'
expect "ints, bools, a loop"      0 '7
true
ivec2(3, -3)
120' '' -- eval '1 + 2 * 3' '2.0 > 1.0' 'ivec2(3, -3)' 'int p = 1; for (int i = 2; i <= 5; i++) p *= i; p'
expect "loop bound is an error"   1 '' "error: column 12: more than 100 loop iterations (the bound: --max-iterations)" -- eval --max-iterations 100 'int i = 0; while (true) i++; i'
expect "defines"                  0 '0.75' '' -- eval -D 'x=0.5' -D 'y=x*x' 'y + x'
expect "reflect"                  0 'vec3(1, 1, 0)' '' -- eval 'reflect(vec3(1,-1,0), vec3(0,1,0))'
expect "matrix times vector"      0 'vec2(4, 6)' '' -- eval 'mat2(1,2,3,4) * vec2(1,1)'
expect "inverse"                  0 'mat2(-2, 1, 1.5, -0.5)' '' -- eval 'inverse(mat2(1,2,3,4))'
expect "mod takes the sign of y"  0 'vec2(2, -2)' '' -- eval 'vec2(mod(-1., 3.), mod(1., -3.))'

# precisions: the same expression in each
expect "highp inversesqrt tiny"   0 '1.0000027e+20' '' -- eval 'inversesqrt(1e-40)'
expect "double inversesqrt tiny"  0 '1e+20' '' -- eval --precision double 'inversesqrt(1e-40)'
expect "mediump flushes 1e-40"    0 'inf' '~inversesqrt: x <= 0 is outside the GLSL ES domain' -- eval --precision mediump 'inversesqrt(1e-40)'
expect "mediump rounds to half"   0 '0.3333' '' -- eval -p mediump '1.0/3.0'
expect "lowp saturates"           0 '1.996' '' -- eval -p lowp '1.5 + 1.5'
expect "highp shortest decimal"   0 '0.1' '' -- eval '0.1'
expect "double shortest decimal"  0 '0.30000000000000004' '' -- eval -p double '0.1 + 0.2'
expect "highp sum"                0 '0.3' '' -- eval '0.1 + 0.2'
expect "negative zero kept"       0 '-0' '' -- eval -- '-0.0'

# hyperbolic functions in every precision (libm's binary64 values, rounded to binary32, then
# to binary16 or lowp), with vector overloads
set -- 'sinh(1.0)' 'vec2(cosh(1.0), tanh(0.5))' 'vec3(asinh(1.0), acosh(2.0), atanh(0.5))'
expect "hyperbolic double"        0 '1.1752011936438014
vec2(1.5430806348152437, 0.46211715726000974)
vec3(0.881373587019543, 1.3169578969248166, 0.5493061443340548)' '' -- eval -p double "$@"
expect "hyperbolic highp"         0 '1.1752012
vec2(1.5430807, 0.46211717)
vec3(0.8813736, 1.316958, 0.54930615)' '' -- eval "$@"
expect "hyperbolic mediump"       0 '1.175
vec2(1.543, 0.4622)
vec3(0.8813, 1.317, 0.5493)' '' -- eval -p mediump "$@"
expect "hyperbolic lowp"          0 '1.176
vec2(1.543, 0.46)
vec3(0.883, 1.316, 0.55)' '' -- eval -p lowp "$@"
expect "sinh tiny is x, overflow" 0 'vec3(-1e-30, inf, 1)' '' -- eval 'vec3(sinh(-1e-30), cosh(90.0), tanh(10.0))'
expect "acosh domain warning"     0 'nan' '~acosh: x < 1 is outside the GLSL ES domain' -- eval 'acosh(0.5)'
expect "atanh pole"               0 '-inf' '~atanh: |x| >= 1 is outside the GLSL ES domain' -- eval 'atanh(-1.0)'
expect "round halves to even"     0 'vec4(2, -2, 4, -0)' '' -- eval 'round(vec4(2.5, -2.5, 3.5, -0.3))'
expect "roundEven and trunc"      0 'vec3(2, -2, 0)' '' -- eval 'vec3(roundEven(1.5), trunc(-2.7), trunc(0.9))'
expect "modf fraction"            0 '-0.75' '' -- eval 'float i; modf(-2.75, i)'
expect "modf whole part"          0 '-2' '' -- eval 'float i; modf(-2.75, i); i'
expect "modf needs its out i"     2 '' "error: column 1: modf takes (x, out i) of one type, float or vecN; not (float, ...)" -- eval 'modf(1.5)'

# output formats
expect "hex highp"                0 '0x3fb504f3' '' -- eval --hex 'pow(2.0, 0.5)'
expect "hex mediump"              0 'vec2(0x3c00, 0xc000)' '' -- eval --hex -p mediump 'vec2(1, -2)'
expect "hex double"               0 '0x3ff0000000000000' '' -- eval --hex -p double '1.0'
expect "hex int"                  0 '0xffff' '' -- eval --hex -p mediump -- '-1'
expect "ulp exact"                0 '0.5  # ulp: 0' '' -- eval --ulp '1.0 / 2.0'
expect "ulp mediump"              0 '1258  # ulp: 2.69' '' -- eval -p mediump --ulp 'exp2(10.3)'
expect "json"                     0 '{"expression": "mat2(1,2,3,4) * vec2(1,1)", "precision": "highp", "type": "vec2", "value": [4, 6]}' '' -- eval --format json 'mat2(1,2,3,4) * vec2(1,1)'
expect "json nan as string"       0 '{"expression": "log(-1.0)", "precision": "highp", "type": "float", "value": "nan"}' '*' -- eval -f json 'log(-1.0)'
expect "json escapes"             0 '{"expression": "1.0\t+ 1.0", "precision": "highp", "type": "float", "value": 2}' '' -- eval -f json "$(printf '1.0\t+ 1.0')"
expect "csv one type"             0 'expression,x,y,z
"normalize(vec3(3,0,4))",0.6,0,0.8
vec3(1),1,1,1' '' -- eval --format csv 'normalize(vec3(3,0,4))' 'vec3(1)'
expect "csv mixed types"          0 'expression,type,c0,c1,c2
1.0,float,1,,
"vec3(1,2,3)",vec3,1,2,3' '' -- eval -f csv '1.0' 'vec3(1,2,3)'
expect "csv ulp columns"          0 'expression,value,value_ulp
0.5,0.5,0' '' -- eval -f csv --ulp '0.5'
expect "csv matrix columns"       0 'expression,c0r0,c0r1,c1r0,c1r1
"mat2(1,2,3,4)",1,2,3,4' '' -- eval -f csv 'mat2(1,2,3,4)'
expect_stdin "stdin expressions" '1.0 + 1.0
# a comment

vec2(3)
' 0 '2
vec2(3, 3)' '' -- eval

# domain: defined result and a warning, --strict makes it an error
expect "pow domain warning"       0 'nan' 'warning: column 1: pow: x < 0 is outside the GLSL ES domain; the result is the IEEE value of its formula' -- eval 'pow(-2.0, 0.5)'
expect "acos domain warning"      0 'nan' '~acos: |x| > 1 is outside the GLSL ES domain' -- eval 'acos(1.5)'
expect "inversesqrt(0) warning"   0 'inf' '~inversesqrt: x <= 0' -- eval 'inversesqrt(0.0)'
expect "strict is an error"       1 '' 'error: column 1: pow: x < 0 is outside the GLSL ES domain (--strict)' -- eval --strict 'pow(-2.0, 0.5)'
expect "strict passes clean"      0 '2' '' -- eval --strict 'sqrt(4.0)'
expect "warning names expression" 0 '1
nan' '~warning: expression 2: column 12: log: x <= 0 is outside the GLSL ES domain; the result is the IEEE value of its formula' -- eval '1.0' 'log(0.0) - log(0.0)'

# usage errors
expect "syntax error column"      2 '' "error: column 5: expected an expression, found end of input" -- eval '1 + '
expect "unknown variable"         2 '' "error: column 1: unknown variable 'x'" -- eval 'x'
expect "second expression error"  2 '' "error: expression 2: column 1: unknown function 'foo'" -- eval '1' 'foo(1)'
expect "bad define"               2 '' "error: eval: -D 'x': expected NAME=EXPR" -- eval -D x '1'
expect "define error"             2 '' "error: -D 'y': column 8: operator '+': operands vec2 and vec3 do not match (GLSL ES converts nothing implicitly)" -- eval -D 'y=vec2(1)+vec3(1)' '1'
expect "bad precision"            2 '' "error: eval: unknown precision 'half' (double, highp, mediump, lowp)" -- eval -p half '1'
expect "bad format"               2 '' "error: eval: unknown format 'xml' (glsl, csv, jsonl)" -- eval -f xml '1'
expect "unknown option"           2 '' "~unknown option '--frob'" -- eval --frob '1'
expect "help"                     0 '~usage: shadecalc eval' '' -- eval --help

# long flat expressions: evaluated without recursion (a chain is as deep as it is long)
chain4000=$(awk 'BEGIN { s = "1"; for (i = 1; i < 4000; i++) s = s "+1"; print s }')
fchain4000=$(awk 'BEGIN { s = "1.0"; for (i = 1; i < 4000; i++) s = s "+1.0"; print s }')
expect "4000-term chain"          0 '4000' '' -- eval "$chain4000"
expect "4000-term chain in -D"    0 '4001' '' -- eval -D "x=$chain4000" 'x + 1'
expect_stdin "4000-term chain on stdin" "$chain4000" 0 '4000' '' -- eval
expect "4000-term chain in sweep" 0 'x,value
1,4001
2,4002' '' -- sweep --var x=1,2 "x + $fchain4000"
# one argument is at most 128 KiB (Linux MAX_ARG_STRLEN): 60 000 terms, 120 KB
chain60k=$(awk 'BEGIN { s = "1"; for (i = 1; i < 60000; i++) s = s "+1"; print s }')
expect "60000-term chain"         0 '60000' '' -- eval "$chain60k"
# ~1 MB on standard input; alternating signs keep every partial sum exact in highp
expect_stdin "1 MB chain on stdin" "$(awk 'BEGIN { for (i = 0; i < 250000; i++) printf "+1-1"; print "+7" }')" 0 '7' '' -- eval
nest=$(awk 'BEGIN { for (i = 0; i < 300; i++) printf "-("; printf "1"; for (i = 0; i < 300; i++) printf ")" }')
expect "deep nesting names the limit" 2 '' '~nested too deeply (more than 256 levels of parentheses, calls, operators and blocks)' -- eval -- "$nest"

# standard input: streamed line by line, bad lines reported by number, read errors reported
# stdin_run NAME STATUS STDOUT STDERR -- ARGS... < INPUT: like expect (exact outputs), with a file
# or a device on standard input
stdin_run() {
    name=$1 want_status=$2 want_out=$3 want_err=$4; shift 5
    "$SHADECALC" "$@" >"$e2e_tmp/out" 2>"$e2e_tmp/err"
    verdict "$name" [ "$?:$(cat "$e2e_tmp/out"):$(cat "$e2e_tmp/err")" = "$want_status:$want_out:$want_err" ]
}
stdin_run "directory on stdin" 1 '' 'error: eval: standard input: Is a directory' -- eval <"$e2e_tmp"
stdin_run "/dev/zero on stdin" 2 '' 'error: line 1: longer than 1048576 bytes' -- eval </dev/zero
printf '1\n2\0003\n4\n' >"$e2e_tmp/nul"
stdin_run "NUL byte names its line" 2 '1
4' 'error: line 2: contains a NUL byte' -- eval <"$e2e_tmp/nul"
expect_stdin "bad lines are reported, the others printed" '1 + 1
2 +

vec2(3)
foo
# a comment
4
' 2 '2
vec2(3, 3)
4' "error: line 2: column 4: expected an expression, found end of input
error: line 5: column 1: unknown variable 'foo'" -- eval
expect_stdin "CRLF lines"                "$(printf '1\r\n2\r\n')" 0 '1
2' '' -- eval
expect_stdin "strict domain error goes on" 'sqrt(-1.0)
2' 1 '2' 'error: line 1: column 1: sqrt: x < 0 is outside the GLSL ES domain (--strict)' -- eval --strict
expect_stdin "csv header from the first line" '1.0
vec2(1)
3.0' 2 'expression,value
1.0,1
3.0,3' 'error: line 2: a vec2 in csv under the header of a float (the first line'"'"'s type): give expressions of one type, or several as arguments' -- eval -f csv

# endless input: results stream out (and the run ends when the reader does)
verdict "endless input streams" [ "$(yes '1 + 1' | timeout 20 "$SHADECALC" eval | head -n 3 | tr '\n' ' ')" = "2 2 2 " ]
# with SIGPIPE ignored, a closed output ends the run with an error instead of reading forever
timeout 20 sh -c 'trap "" PIPE; yes 1 2>/dev/null | "$1" eval 2>"$2" | head -n 1 >/dev/null' sh "$SHADECALC" "$e2e_tmp/err"
verdict "closed output stops endless input" grep -q 'eval: standard output: write error' "$e2e_tmp/err"
# a co-process reads each result before it writes the next line: only a flush per line on a
# pipe lets this finish
mkfifo "$e2e_tmp/answers"
timeout 20 sh -c '{ echo "1 + 1"; read -r a <&3; echo "$a * 10"; read -r b <&3; echo "$b" >"$1.last"; } 3<"$1" | "$2" eval >"$1"' sh "$e2e_tmp/answers" "$SHADECALC"
verdict "results flushed line by line on a pipe" [ "$(cat "$e2e_tmp/answers.last" 2>/dev/null)" = 20 ]
# 200 000 lines in constant memory: under a 64 MB address-space limit (not for sanitizer builds,
# whose shadow memory alone needs more address space than that)
if (ulimit -v 65536 && "$SHADECALC" eval 1) >/dev/null 2>&1; then
    (ulimit -v 65536
     expect_stdin "200000 lines in 64 MB" "$(awk 'BEGIN { for (i = 0; i < 200000; i++) print i ".0 + 0.5" }')" 0 \
         "$(awk 'BEGIN { for (i = 0; i < 200000; i++) printf "%.1f\n", i + 0.5 }')" '' -- eval)
fi
