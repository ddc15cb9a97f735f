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
