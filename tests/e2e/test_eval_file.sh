# shadecalc eval --file: programs in GLSL ES 3.00 (every construct), errors with FILE:LINE:COLUMN,
# integer edge cases with the results the man page defines, bounded loops, rejected recursion.
. tests/e2e/lib.sh

prog() { # NAME TEXT: writes the program $e2e_tmp/NAME.glsl
    printf '%s\n' "$2" >"$e2e_tmp/$1.glsl"
}

# Every construct: a function with in/out/inout parameters, overloads, loops, conditionals,
# const, scopes. Values by hand: 5! = 120; the odd numbers below 20 sum to 10^2 = 100.
prog constructs '#version 300 es
precision highp float;
const float HALF = 0.5;
int fact(int n) { int p = 1; for (int i = 2; i <= n; i++) p *= i; return p; }
float twice(float x) { return 2.0 * x; }
int twice(int x) { return 2 * x; }
void split(in float x, out int whole, inout float acc) { whole = int(x); acc += x - float(whole); }
fact(5);
int s = 0;
for (int i = 0; i < 20; i++) { if (i % 2 == 0) continue; s += i; }
s;
int n = 0; while (true) { n++; if (n == 7) break; } n;
int d = 10; do d -= 3; while (d > 0); d;
twice(HALF); twice(3);
int w; float acc = 1.0; split(2.75, w, acc); ivec2(w, int(acc * 4.0));
{ int s = 1; s; } s; // only top-level expressions print
s > 50 ? vec2(1.0) : vec2(0.0);
true && !false ^^ false;
mat2x3(1, 2, 3, 4, 5, 6) * vec2(1, -1);
bvec3(lessThan(ivec3(1, 5, 3), ivec3(2, 2, 3)))'
expect "file: every construct" 0 '120
100
7
-2
1
6
ivec2(2, 7)
100
vec2(1, 1)
true
vec3(-3, -3, -3)
bvec3(true, false, false)' '' -- eval --file "$e2e_tmp/constructs.glsl"

expect_stdin "file: standard input" '1 + 2; uvec2(7u) / 2u' 0 '3
uvec2(3, 3)' '' -- eval --file -

# integers: highp wraps at 32 bits, mediump at 16, lowp at 9; division truncates toward zero
prog ints '2147483647 + 1; -7 / 2; -7 % 3; 0u - 1u; ~0; 0xFF & 017; -2147483648 / -1'
expect "file: highp ints wrap"   0 '-2147483648
-3
-1
4294967295
-1
15
-2147483648' '' -- eval --file "$e2e_tmp/ints.glsl"
expect_stdin "file: mediump ints wrap at 16 bits" '32767 + 1; 65535u + 1u' 0 '-32768
0' '' -- eval -p mediump --file -
expect_stdin "file: lowp ints wrap at 9 bits" '255 + 1' 0 '-256' '' -- eval -p lowp --file -
expect_stdin "file: division by zero" '7 / 0; 7u % 0u' 0 '-1
4294967295' '~:1:3: operator '"'/'"': division by zero is undefined in GLSL ES' -- eval --file -
expect_stdin "file: division by zero --strict" '7 / 0' 1 '' \
    'error: <stdin>:1:3: operator '"'/'"': division by zero is outside the GLSL ES domain (--strict)' -- eval --strict --file -
expect_stdin "file: shift past the width" '1 << 33; 1 << -1' 0 '2
-2147483648' '~shift count outside 0..31' -- eval --file -
expect_stdin "file: float to int saturates" 'int(1e20); int(-3.7); uint(-1.0)' 0 '2147483647
-3
0' '' -- eval --file -
expect_stdin "file: hex of ints" 'ivec2(-1, 255)' 0 'ivec2(0xffffffff, 0x000000ff)' '' -- eval --hex --file -

# formats
expect_stdin "file: jsonl" 'ivec2(1, 2);
true' 0 '{"expression": "ivec2(1, 2)", "line": 1, "precision": "highp", "type": "ivec2", "value": [1, 2]}
{"expression": "true", "line": 2, "precision": "highp", "type": "bool", "value": true}' '' -- eval -f jsonl --file -
expect_stdin "file: a structure prints member by member" 'struct S { float w[2]; int n; };
S s = S(float[2](0.5, 1.5), 3);
s' 0 '{"expression": "s.w[0]", "line": 3, "precision": "highp", "type": "float", "value": 0.5}
{"expression": "s.w[1]", "line": 3, "precision": "highp", "type": "float", "value": 1.5}
{"expression": "s.n", "line": 3, "precision": "highp", "type": "int", "value": 3}' '' -- eval -f jsonl --file -
expect_stdin "file: csv" 'vec2(1.0, 2.0); vec2(0.5)' 0 'expression,x,y
"vec2(1.0, 2.0)",1,2
vec2(0.5),0.5,0.5' '' -- eval -f csv --file -
expect_stdin "file: csv of two types" '1.0; 2' 2 'expression,value
1.0,1' 'error: <stdin>:1: a int in csv under the header of a float (the first value'"'"'s type): print values of one type' -- eval -f csv --file -
expect_stdin "file: defines are inputs" 'x * 2.0; v.zyx' 0 '1
vec3(3, 2, 1)' '' -- eval -D x=0.5 -D 'v=vec3(1,2,3)' --file -

# errors: FILE:LINE:COLUMN, exit 2 (compile) or 1 (run)
prog typeerr 'float x = 1.0;
int y = 2;
x + y;'
expect "file: type error names line and column" 2 '' \
    "error: $e2e_tmp/typeerr.glsl:3:3: operator '+': operands float and int do not match (GLSL ES converts nothing implicitly: write a float literal (1.0, not 1) or convert (float(...)))" \
    -- eval --file "$e2e_tmp/typeerr.glsl"
expect_stdin "file: recursion rejected" 'int f(int n) {
  return n <= 1 ? 1 : n * f(n - 1);
}' 2 '' "error: <stdin>:2:27: 'f' calls itself: GLSL ES forbids recursion" -- eval --file -
expect_stdin "file: infinite loop bounded" 'int i = 0;
for (;;) i++;' 1 '' 'error: <stdin>:2:1: more than 10000000 loop iterations (the bound: --max-iterations)' -- eval --file -
expect_stdin "file: --max-iterations" 'int i = 0; while (i < 100) i++; i' 1 '' \
    '~more than 50 loop iterations' -- eval --max-iterations 50 --file -
expect_stdin "file: loop within the bound" 'int i = 0; while (i < 100) i++; i' 0 '100' '' -- eval --max-iterations 100 --file -
expect_stdin "file: index out of range" 'vec3 v; int i = 3; v[i]' 1 '' \
    'error: <stdin>:1:21: index 3 is out of range 0..2' -- eval --file -
expect_stdin "file: array index out of range" 'float a[2] = float[2](1.0, 2.0);
int i = 2; a[i - 1]; a[i]' 1 '2' 'error: <stdin>:2:23: index 2 is out of range 0..1' -- eval --file -
expect_stdin "file: unknown function" 'lessThn(1, 2)' 2 '' \
    "error: <stdin>:1:1: unknown function 'lessThn' (did you mean 'lessThan'?)" -- eval --file -
expect_stdin "file: malformed" 'int x = ;' 2 '' "error: <stdin>:1:9: expected an expression, found ';'" -- eval --file -
expect_stdin "file: unterminated comment" '1; /* no end' 2 '' 'error: <stdin>:1:4: unterminated comment: '"'/'" -- eval --file -
expect_stdin "file: a control character" "$(printf '1;\001')" 2 '' '~<stdin>:1:3: unexpected character' -- eval --file -
printf '1;\0002;' >"$e2e_tmp/nul.glsl"
expect "file: a NUL byte" 2 '' "error: eval: $e2e_tmp/nul.glsl: contains a NUL byte (not a text file)" -- eval --file "$e2e_tmp/nul.glsl"
expect "file: missing file" 2 '' "error: eval: cannot open '$e2e_tmp/none.glsl'" -- eval --file "$e2e_tmp/none.glsl"
expect "file: with expressions" 2 '' 'error: eval: --file takes no expression arguments' -- eval --file - '1.0'
expect "file: with --ulp" 2 '' 'error: eval: --ulp is not supported with --file' -- eval --ulp --file -
expect "file: bad --max-iterations" 2 '' "error: eval: --max-iterations 'x': expected a positive integer" -- eval --max-iterations x --file -

# deep nesting is an error, not a crash
deep=$(awk 'BEGIN { for (i = 0; i < 5000; i++) printf "("; printf "1" }')
expect_stdin "file: deep nesting" "$deep" 2 '' '~nested too deeply' -- eval --file -
deep=$(awk 'BEGIN { for (i = 0; i < 5000; i++) printf "{"; }')
expect_stdin "file: deep blocks" "$deep" 2 '' '~nested too deeply' -- eval --file -
