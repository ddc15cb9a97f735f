# shadecalc normal: surface points and normals, triangles, the normal matrix; formats, errors.
# Reference values are closed forms worked out by hand (comments).
. tests/e2e/lib.sh

# expect_close on the csv body: a wrapper that drops the header line.
printf '#!/bin/sh\n"%s" "$@" | tail -n +2\n' "$SHADECALC" >"$e2e_tmp/csv-body"
chmod +x "$e2e_tmp/csv-body"
csv_close() {
    real=$SHADECALC
    SHADECALC=$e2e_tmp/csv-body
    expect_close "$@"
    SHADECALC=$real
}

# torus R=1 r=0.3 at u=0.25 (φ = 90°), v=0.5 (ψ = 180°): p = (0, R − r, 0), n = −y
expect "torus example csv" 0 'x,y,z,nx,ny,nz
0,0.7,0,0,-1,0' '' -- normal --surface 'torus R=1 r=0.3' --uv 0.25,0.5 --format csv
expect "torus example text" 0 'torus R=1 r=0.3 at u=0.25 v=0.5
  p              (0, 0.7, 0)
  n              (0, -1, 0)' '' -- normal --surface 'torus R=1 r=0.3' --uv 0.25,0.5
# dS/du = 2π(R + r cos ψ)(−sin φ, cos φ, 0) = (−1.4π, 0, 0); dS/dv = 2πr(−sin ψ cos φ, −sin ψ sin φ, cos ψ)
csv_close "torus derivatives" 1e-15 '0 0.7 0 0 -1 0 -4.39822971502571 0 0 0 0 -1.8849555921538759 0' \
    -- normal -s 'torus' -u 0.25,0.5 -e --format csv
expect "explain header" 0 '~x,y,z,nx,ny,nz,dpdu_x,dpdu_y,dpdu_z,dpdv_x,dpdv_y,dpdv_z,degenerate' '' \
    -- normal -s torus -u 0.25,0.5 -e -f csv
# sphere r=2 at u=0.125 (φ = 45°), v=0.5 (θ = 90°): p = 2(cos 45°, sin 45°, 0), n = p/2
csv_close "sphere equator" 1e-15 '1.4142135623730951 1.4142135623730951 0 0.7071067811865476 0.7071067811865476 0' \
    -- normal -s 'sphere r=2' -u 0.125,0.5 -f csv
# user surface z = u·v (a saddle) at (0.5, 0.5): S_u = (1, 0, v), S_v = (0, 1, u), n ∝ (−v, −u, 1)
csv_close "user saddle by AD" 1e-15 '0.5 0.5 0.25 -0.408248290463863 -0.408248290463863 0.816496580927726' \
    -- normal -s 'user x=u y=v z=u*v' -u 0.5,0.5 -f csv
# cylinder r=1 h=2 at φ = 0: p = (1, 0, h(v − ½)), n = +x
expect "two points" 0 'x,y,z,nx,ny,nz
1,0,1,1,0,0
1,0,-1,1,0,0' '' -- normal -s 'cylinder r=1 h=2' -u 0,1 -u 0,0 -f csv
# the south pole: degenerate, the documented limit normal (0, 0, −1) to within 4e-9
expect "pole explained" 0 '~the cross product vanishes' '' -- normal -s sphere -u 0.3,0 -e
expect "pole degenerate flag" 0 '~,1' '' -- normal -s sphere -u 0.3,0 -e -f csv

# triangles: (P2 − P1) × (P3 − P1)
expect "triangle csv" 0 'nx,ny,nz,area,degenerate
0,0,1,0.5,0' '' -- normal --triangle 0,0,0 1,0,0 0,1,0 -f csv
expect "triangle text" 0 'triangle (1, 1, 1) (1, 4, 1) (1, 1, 5)
  area           6
  n              (1, 0, 0)' '' -- normal --triangle 1,1,1 1,4,1 1,1,5
expect "collinear triangle" 0 'nx,ny,nz,area,degenerate
0,0,0,0,1' '' -- normal --triangle 0,0,0 1,2,3 2,4,6 -f csv
expect "triangle missing point" 2 '' "error: normal: --triangle: '(missing)': expected three points X,Y,Z X,Y,Z X,Y,Z" \
    -- normal --triangle 0,0,0 1,0,0

# normal matrix: diag(2,4,5) -> diag(1/2, 1/4, 1/5), csv column-major
expect "scale csv" 0 'c0r0,c0r1,c0r2,c1r0,c1r1,c1r2,c2r0,c2r1,c2r2
0.5,0,0,0,0.25,0,0,0,0.2' '' -- normal --matrix 'scale(2,4,5)' --format csv
expect "rigid shortcut" 0 '~orthogonal (a rigid transform): R = M3' '' \
    -- normal --matrix 'rotate(30,0,1,0)*translate(1,2,3)' --explain
# 16 numbers, column-major: x' = x + 2y, so R = (M3⁻¹)ᵀ has the column (1, −2, 0) first... by hand:
# M3 = [[1,2,0],[0,1,0],[0,0,1]], M3⁻¹ = [[1,−2,0],[0,1,0],[0,0,1]], R = [[1,0,0],[−2,1,0],[0,0,1]]
expect "sixteen numbers" 0 'c0r0,c0r1,c0r2,c1r0,c1r1,c1r2,c2r0,c2r1,c2r2
1,-2,0,0,1,0,0,0,1' '' -- normal --matrix '1,0,0,0, 2,1,0,0, 0,0,1,0, 7,8,9,1' -f csv
expect "singular" 2 '' 'error: normal: --matrix scale(1,0,1): the upper-left 3x3 is singular: it has no normal matrix' \
    -- normal --matrix 'scale(1,0,1)'
expect "bad chain" 2 '' "~error: normal: --matrix: matrix: 'skew(1)' at column 1" -- normal --matrix 'skew(1)'

# usage errors
expect "no mode" 2 '' "error: normal: give exactly one of --surface, --triangle, --matrix (see 'shadecalc normal --help')" -- normal
expect "two modes" 2 '' '~give exactly one of' -- normal -s sphere -u 0,0 -m 'scale(1)'
expect "surface without uv" 2 '' 'error: normal: --surface needs --uv U,V' -- normal -s sphere
expect "uv outside" 2 '' 'error: normal: --uv 0.5,1.5: expected U,V with both in [0,1]' -- normal -s sphere -u 0.5,1.5
expect "bad surface" 2 '' "error: normal: --surface: surface 'cube': unknown (expected sphere, torus, plane, cylinder or user)" \
    -- normal -s cube -u 0,0
expect "bad expression" 2 '' '~error: normal: --surface: surface user: z=u+: column' -- normal -s 'user x=u y=v z=u+' -u 0,0
expect "bad format" 2 '' "error: normal: unknown format 'json' (text, csv)" -- normal -s sphere -u 0,0 -f json
expect "unknown option" 2 '' '~error: normal:' -- normal --bogus
expect "extra argument" 2 '' "error: normal: unexpected argument 'x'" -- normal -s sphere -u 0,0 x
expect "help" 0 '~usage: shadecalc normal --surface SPEC' '' -- normal --help

# size does not change a normal (issue 11 §7): the closed form (−0.25, 0.7694208843, −0.5877852523)
expect "sphere r=1e308" 0 '~n              (-0.25, 0.7694208843, -0.5877852523)' '' -- normal --surface 'sphere r=1e308' --uv 0.3,0.3
expect "sphere r=1e-308" 0 '~n              (-0.25, 0.7694208843, -0.5877852523)' '' -- normal --surface 'sphere r=1e-308' --uv 0.3,0.3
expect "user surface 1e200" 0 '~n              (0.8090169944, 0.5877852523, 0)' '' -- normal --surface 'user x=1e200*cos(6.283185307179586*u) y=1e200*sin(6.283185307179586*u) z=1e200*v' --uv 0.1,0.5
expect "triangle 1e308" 0 '~n              (0, 0, 1)' '' -- normal --triangle 0,0,0 1e308,0,0 0,1e308,0
expect "triangle 1e-200" 0 '~n              (0, 0, 1)' '' -- normal --triangle 0,0,0 1e-200,0,0 0,1e-200,0
