# shadecalc check: albedo tables, flags, formats, errors.
. tests/e2e/lib.sh

expect "blinn-phong peak exceeds 1" 0 '~max albedo 1.075201 at theta_i = 0: EXCEEDS 1 (not energy conserving)' '' -- check --brdf 'blinn-phong diff=0 spec=1 m=8.8' --theta 0,45
expect "lambert conserves"          0 '~<= 1 (energy conserving)' '' -- check --brdf lambert --theta 0,60
expect "original phong"             0 '~reciprocity error 0.983: NOT RECIPROCAL' '' -- check --brdf 'phong form=original diff=0 spec=1 m=10' --theta 0,89.9
expect "gmd reciprocal"             0 '~reciprocity error 0: reciprocal' '' -- check --brdf 'ward form=gmd diff=0 spec=1 alpha=0.2' --theta 0
expect "csv header"                 0 '~brdf,theta_i,albedo_r,albedo_g,albedo_b,error,max_albedo,reciprocity_error,energy_conserving,reciprocal
"lambert diff=0.5",0,0.5,0.5,0.5,' '' -- check -f csv --brdf 'lambert diff=0.5' --theta 0
expect "csv flags"                  0 '~,0.5,0,1,1' '' -- check -f csv --brdf 'lambert diff=0.5' --theta 0
expect "no brdf"                    2 '' "error: check: no --brdf SPEC given (see 'shadecalc check --help')" -- check
expect "legacy model"               2 '' "error: check: 'opengl' is a legacy shading model, not a BRDF" -- check --brdf opengl
expect "bad theta"                  2 '' 'error: check: --theta 0,95: expected up to 64 angles in [0, 90) separated by commas' -- check --brdf lambert --theta 0,95
expect "bad order"                  2 '' 'error: check: --order 1: expected an integer 2..32' -- check --brdf lambert --order 1
expect "bad spec"                   2 '' "error: brdf ward: unknown key 'm' (a key of other kinds)" -- check --brdf 'ward m=3'
expect "help"                       0 '~usage: shadecalc check' '' -- check --help

# narrow lobes (issue 11 §7): resolved up to a width of 1e-6 rad, else said so
# a(0) of normalized Blinn-Phong is (m+8)(2/(m+4) − 1/(m+2)) = 1 + 2e-12 at m = 1e12: within the
# error the check reports, which is below 2e-4
out=$("$SHADECALC" check -f csv --brdf 'blinn-phong diff=0 spec=1 m=1e12' --theta 0 | tail -1)
if echo "$out" | awk -F, '{ d = $3 - 1; if (d < 0) d = -d; exit !(d <= $6 && $6 < 2e-4) }'; then
    echo "ok   narrow lobe resolved"; echo pass >>"$E2E_COUNTS"
else
    echo "FAIL narrow lobe resolved: got [$out]"; echo fail >>"$E2E_COUNTS"
fi
expect "lobe too narrow"            0 '~UNRESOLVED (a lobe narrower than the quadrature resolves)' '' -- check --brdf 'blinn-phong diff=0 spec=1 m=1e15' --theta 0
# check integrates the model, not shade's floor max(cos θ_o, 1e-6): Ward–Dür's albedo at 60° is
# 0.916914559 and at 89° 3.37534109 (tensor Gauss–Legendre, 20 nodes × 64 and × 128 panels a side
# in long double; the floor's band took 6.3e-8 and 3.5e-7 off)
expect "duer at 60"                 0 '~"ward form=duer diff=0 spec=1 alpha=0.2",60,0.916914559,' '' -- check -f csv --brdf 'ward form=duer diff=0 spec=1 alpha=0.2' --theta 60
expect "duer at 89"                 0 '~"ward form=duer diff=0 spec=1 alpha=0.2",89,3.37534109,' '' -- check -f csv --brdf 'ward form=duer diff=0 spec=1 alpha=0.2' --theta 89
