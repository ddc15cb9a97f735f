# shadecalc shade with the legacy models (ads, opengl, direct3d9) from the command line, against
# closed forms (man page MODELS; reference §3-§4), and the option errors of shade.
. tests/e2e/lib.sh

# l = dir(60,0), v its mirror dir(60,180): r = v and h = n, so S = 1 for phong and blinn-phong:
# L = k_d cos 60° + k_s = 0.5*0.5 + 0.25; lambert has no specular term.
l60='directional dir=0.8660254037844386,0,0.5'
v60='-0.8660254037844386,0,0.5'
expect_close "ads blinn-phong mirror"  1e-14 '0.5 0.5 0.5' -- shade -p double -l "$l60" -b 'ads diff=0.5 spec=0.25 m=32' --v "$v60"
expect_close "ads phong mirror"        1e-14 '0.5 0.5 0.5' -- shade -p double -l "$l60" -b 'ads form=phong diff=0.5 spec=0.25 m=32' --v "$v60"
expect_close "ads lambert"             1e-14 '0.25 0.25 0.25' -- shade -p double -l "$l60" -b 'ads form=lambert diff=0.5 spec=0.25 m=32' --v "$v60"
# v = n: phong r·v = cos 60° = 1/2, blinn-phong n·h = cos 30°; k_s (·)^4 on top of 0.25
expect_close "ads phong v = n"         1e-14 '0.265625 0.265625 0.265625' -- shade -p double -l "$l60" -b 'ads form=phong diff=0.5 spec=0.25 m=4'
expect_close "ads blinn-phong v = n"   1e-14 '0.390625 0.390625 0.390625' -- shade -p double -l "$l60" -b 'ads diff=0.5 spec=0.25 m=4'
# the per-light and global ambient terms: k_a (L_A + L_A,1) = 0.5 (0.2 + 0.4), not attenuated;
# the light is below the surface (lambert: no specular term)
expect_close "ads ambient"             1e-14 '0.3 0.3 0.3' -- shade -p double -l 'point pos=0,0,-2 amb=0.4' -b 'ads form=lambert amb=0.5' --ambient 0.2

# Direct3D 9: a point light 5 away (clq, att = 1) is cut off beyond range=, kept at it;
# e = 0.1, diffuse 0.3, ambient a_cm a_cl = 0.1, specular 0.25 (n·h = 1, m = 0)
d3d='direct3d9 emission=0.1 amb=0.1 diff=0.3 spec=0.25'
expect_close "direct3d9 beyond range"  1e-14 '0.1 0.1 0.1' -- shade -p double -l 'point pos=0,0,5 atten=clq sc=1 amb=1 range=4.999' -b "$d3d"
expect_close "direct3d9 at range"      1e-14 '0.75 0.75 0.75' -- shade -p double -l 'point pos=0,0,5 atten=clq sc=1 amb=1 range=5' -b "$d3d"
# a light below the horizon (θ_i = 100°): no diffuse; Direct3D 9 keeps s (n·ĥ)^2 = 0.5 cos² 50°,
# OpenGL gates it; both add e + a_cm a_cs = 0.1 + 0.2*0.3 (the GL material ambient 0.2)
below='directional dir=0.984807753012208,0,-0.1736481776669303'
expect_close "direct3d9 no n.l gate"   1e-12 '0.3665879555832674 0.3665879555832674 0.3665879555832674' -- shade -p double -l "$below" -b 'direct3d9 emission=0.1 spec=0.5 m=2' --ambient 0.3
expect_close "opengl n.l gate"         1e-14 '0.16 0.16 0.16' -- shade -p double -l "$below" -b 'opengl emission=0.1 spec=0.5 m=2' --ambient 0.3

# OpenGL separate specular, l = v = n: primary e + a_cm a_cs + d = 0.25*0.5 + 0.75 = 0.875,
# secondary 0.5; the sum 1.375 clamps to 1
sep='opengl separate-specular=1 amb=0.25 diff=0.75 spec=0.5 m=10'
expect "explain separate specular"  0 '~primary (0.875, 0.875, 0.875)  secondary (0.5, 0.5, 0.5)
L_o = 1 1 1' '' -- shade -p double -e -l 'directional dir=0,0,1' -b "$sep" --ambient 0.5
expect "json separate specular"     0 '~"primary": [0.875, 0.875, 0.875], "secondary": [0.5, 0.5, 0.5]}' '' -- shade -p double -e -f json -l 'directional dir=0,0,1' -b "$sep" --ambient 0.5
expect "explain names light kinds"  0 '~light 2 (point)' '' -- shade -e -l 'directional dir=0,0,1' -l 'point pos=0,0,1'
expect "json names light kinds"     0 '~"lights": [{"kind": "directional", ' '' -- shade -e -f json -l 'directional dir=0,0,1'

# option errors
expect "unknown format"     2 '' "error: shade: unknown format 'xml' (text, csv, json)" -- shade -f xml -l 'directional dir=0,0,1'
expect "unknown precision"  2 '' "error: shade: unknown precision 'quad' (double, highp, mediump, lowp)" -- shade -p quad -l 'directional dir=0,0,1'
expect "unknown option"     2 '' "~error: shade: unknown option '--frob'" -- shade --frob -l 'directional dir=0,0,1'
expect "option needs value" 2 '' "~error: shade: option '--light' needs a value" -- shade --light
