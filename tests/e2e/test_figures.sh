# Every figure the presets and the README draw, checked mechanically by svg_check.py: text and
# curves inside the viewBox, legend text inside the legend, no two curves in the same style.
. tests/e2e/lib.sh

figures() { # NAME ARGS...: draws NAME.svg with `shadecalc sweep ARGS...`
    name=$1; shift
    expect "figure $name" 0 '' '' -- sweep --plot "$e2e_tmp/$name.svg" "$@"
}
for p in attenuation spot lobe albedo area-distance area-roughness; do
    figures "preset-$p" --preset "$p"
done
figures readme-attenuation --var r=0:12:121 --light 'point pos=0,0,$r I=1 atten=window rstart=1 rend=10' --brdf lambert
figures readme-lobe --var theta_o=-90:90:181 --var theta_i=0,30,60 --brdf 'blinn-phong diff=0 m=64' --polar
figures roughness --var theta_o=-90:90:181 --var alpha=0.1,0.2,0.4 --brdf 'cook-torrance diff=0 f0=0.9 alpha=$alpha' --polar
figures long-title --var x=0:1:11 --var alpha=0.25,0.5 --title 'cook-torrance diff=0 alpha=0.25, a long title that does not fit in the width of the canvas at all' 'vec3(pow(x, alpha), x, 1.0 - x)'
figures long-legend --preset albedo --var theta_i=0:80:9 --brdf lambert \
    --brdf 'cook-torrance diff=0 D=beckmann G=smith F=exact ior=1.33 spec=0.75,0.5,0.25 perceptual=0.351234567'
verdict "long legend keeps its value" grep -q 'perceptual=0.351234567</text>' "$e2e_tmp/long-legend.svg"
figures grazing-spike --var theta_o=-90:90:181 --var theta_i=0,30,60 --brdf 'cook-torrance alpha=0.2' --polar
expect "figure slice" 0 '' '' -- sweep --var theta_h=0:90:46 --var theta_d=0:90:46 --brdf 'cook-torrance alpha=0.2' --heatmap "$e2e_tmp/slice.svg" --sqrt-x
expect "figure slice linear" 0 '' '' -- sweep --var theta_h=0:90:46 --var theta_d=0:90:46 --brdf 'ward alpha=0.3' --heatmap "$e2e_tmp/slice-linear.svg" --tone linear --exposure 2

verdict "figures are drawn inside their canvas" python3 tests/e2e/svg_check.py "$e2e_tmp"/*.svg
# the checker itself: a text past the right edge and two curves in one style are found
cat >"$e2e_tmp/bad.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100" font-size="12">
<text x="90" y="50">too long</text>
<g class="series" stroke="#000"><polyline points="0,0 1,1" stroke-dasharray=""/></g>
<g class="series" stroke="#000"><polyline points="0,0 1,1" stroke-dasharray=""/></g>
</svg>
SVG
verdict "the checker finds clipped text and twin curves" \
    test "$(python3 tests/e2e/svg_check.py "$e2e_tmp/bad.svg" | wc -l)" = 2
verdict "heat map: theta_d = 0 at the bottom" python3 -c '
import sys, xml.etree.ElementTree as ET
S = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[1]).getroot()
cells = [g for g in root.iter(S + "g") if g.get("class") == "cells"][0].findall(S + "rect")
sys.exit(not (len(cells) == 46 * 46 and float(cells[0].get("y")) > float(cells[-1].get("y"))))' "$e2e_tmp/slice.svg"
expect "heat map of one variable" 2 '' '~draws exactly two variables' -- sweep --var x=0:1:3 --heatmap "$e2e_tmp/h.svg" x
expect "heat map of a decreasing variable" 2 '' '~the variable x must increase' -- sweep --var x=1:0:3 --var y=0:1:3 --heatmap "$e2e_tmp/h.svg" 'x + y'
expect "heat map tone" 2 '' '~expected log or linear' -- sweep --var x=0:1:3 --var y=0:1:3 --tone gamma --heatmap "$e2e_tmp/h.svg" 'x + y'
expect "heat map exposure" 2 '' '~expected a number of stops' -- sweep --var x=0:1:3 --var y=0:1:3 --exposure lots --heatmap "$e2e_tmp/h.svg" 'x + y'
