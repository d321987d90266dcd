#!/bin/sh
# study_test.sh QUADSHADE SOURCE_DIR OUT CASE [PLUGIN]: `quadshade study` as a user runs it, on
# small sizes, for one CASE:
#   catalogue  a catalogue shader with its unfiltered variant on two views, three modes: the rows,
#              the truth each names, the errors' bounds, the derivative maps of its inputs, the
#              report with its images in it
#   plugin     a plugin's shader (PLUGIN), one mode, on the scene's camera and on a camera file
#   glsl       a user's .frag (examples/minimal/stripes.frag), one view, two modes
#   stability  float against double with the coordinates far from the origin (--offset), and the
#              undefined cases a probe meets, marked per pixel
#   bench      bench/study.txt, bench/run-study's study, through `quadshade study --study` with
#              its rows in every case, and bench/results.py rewriting docs/results.md's error
#              table (on a copy) from it
#   refused    bad usage, bad input and outputs over inputs: a clear message, a non-zero exit, no report
# The report is checked in headless Chromium where it is installed (every image loaded).
set -u
qs=$1 src=$2 out=$3 case=$4 plugin=${5:-}
plane=$src/scenes/assets/table-1.1-plane.gltf
small="--size 24 --truth 4 --repeat 2 --threads 1"
rm -rf "$out" && mkdir -p "$out"
fail() { echo "study_test.sh ($case): $*" >&2; exit 1; }

# field CSV ROW_MATCH COLUMN: the column's value on the first row whose line matches ROW_MATCH.
field() {
    awk -F, -v m="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == c) k = i; next }
                                 $0 ~ m { print $k; exit }' "$1"
}
# below A B: A < B as numbers.
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }

check_report() {
    [ -s "$1/report.html" ] || fail "no report.html"
    images=$(grep -o "src='data:image/png;base64," "$1/report.html" | wc -l)
    [ "$images" -ge "$2" ] || fail "report.html holds $images images, expected at least $2"
    grep -q "src='images/\|src='plots/" "$1/report.html" && fail "report.html points at files outside itself"
    if grep -q "class='no-plot'" "$1/report.html"; then
        grep -o "<p class='no-plot'>[^<]*" "$1/report.html" | head -1
    else
        ls "$1"/plots/*.png > /dev/null || fail "plots drawn but not written"
    fi
    if command -v chromium > /dev/null; then
        dom=$(chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=10000 \
            --dump-dom "file://$1/report.html" 2>/dev/null)
        check=$(printf '%s' "$dom" | sed -n 's/.*<p id="image-check">images: \([0-9]*\)\/\([0-9]*\) loaded.*/\1 \2/p')
        set -- $check
        [ $# -eq 2 ] && [ "$1" = "$2" ] && [ "$2" -gt 0 ] || fail "Chromium: not every image loaded ($check)"
        echo "Chromium: $1/$2 images loaded"
    else
        echo "Chromium is not installed: the report's images were checked in its text only"
    fi
}

case $case in
catalogue)
    "$qs" study "$plane" --shader dots_aa --unfiltered dots_aa_step --views camera,grazing --modes fine,dual2,ss2x2 \
        $small -o "$out" || fail "exit $?"
    csv=$out/study.csv
    [ "$(tail -n +2 "$csv" | wc -l)" -eq 6 ] || fail "expected 6 rows (2 views x 3 modes)"
    [ "$(field "$csv" '^dots_aa,camera,ss2x2,' variant)" = dots_aa_step ] ||
        fail "ss2x2 does not render the unfiltered variant"
    [ "$(field "$csv" '^dots_aa,camera,fine,' truth)" = dots_aa_step ] || fail "the truth is not the unfiltered variant"
    grep -q 'dots_aa_step at 4x4 samples per pixel in double, box-filtered' "$out/views.csv" ||
        fail "views.csv names no truth"
    # The fine rule is llvmpipe's: the same image but for float rounding; the truth differs from
    # every mode, and supersampling the step pattern as llvmpipe does matches llvmpipe's.
    below "$(field "$csv" '^dots_aa,camera,fine,' rms_vs_llvmpipe)" 0.002 || fail "fine departs from llvmpipe"
    below "$(field "$csv" '^dots_aa,camera,ss2x2,' max_vs_llvmpipe)" 0.01 || fail "ss2x2 departs from llvmpipe's ss2x2"
    below 0.001 "$(field "$csv" '^dots_aa,grazing,fine,' rms_vs_truth)" ||
        fail "the grazing view matches the truth exactly"
    below "$(field "$csv" '^dots_aa,camera,fine,' ms_min)" "$(field "$csv" '^dots_aa,camera,fine,' ms_max)" ||
        [ "$(field "$csv" '^dots_aa,camera,fine,' ms_min)" = "$(field "$csv" '^dots_aa,camera,fine,' ms_max)" ] ||
        fail "the time's range is reversed"
    [ -s "$out/images/dots_aa-grazing/fine-heat.png" ] || fail "no heat map"
    # Derivative maps of st: exact under every rule in the orthographic camera's affine view; in
    # perspective the quads' one-sided differences depart from the analytic partials, the coarse
    # rules' shared dFdx the more.
    d=$out/derivatives.csv
    [ "$(tail -n +2 "$d" | wc -l)" -eq 12 ] || fail "expected 12 derivative rows (2 views x 2 inputs x 3 rules)"
    below "$(field "$d" '^dots_aa,camera,st.s,coarse-lower,' max_dx)" 1e-6 ||
        fail "camera: coarse dFdx(st.s) is not exact"
    below 1e-4 "$(field "$d" '^dots_aa,grazing,st.t,fine,' rms_dy)" || fail "grazing: fine dFdy(st.t) is exact"
    below "$(field "$d" '^dots_aa,grazing,st.s,fine,' rms_dx)" \
        "$(field "$d" '^dots_aa,grazing,st.s,coarse-upper,' rms_dx)" ||
        fail "grazing: coarse-upper dFdx(st.s) is no worse than fine"
    grep -q '<h3>Derivative maps</h3>' "$out/report.html" || fail "the report has no derivative maps"
    check_report "$out" 40
    # Every output by the output rule: no temporary, staging or scratch folder is left behind.
    leftover=$(find "$out" -name '.*')
    [ -z "$leftover" ] || fail "left behind: $leftover"
    ;;
plugin)
    # Its views: the scene's camera, and the same camera given as a user's camera file.
    "$qs" study "$plane" --plugin "$plugin" --shader stripes --views camera,"$plane" --modes fine $small -o "$out" ||
        fail "exit $?"
    csv=$out/study.csv
    below "$(field "$csv" '^stripes,camera,fine,' rms_vs_llvmpipe)" 0.002 || fail "fine departs from llvmpipe"
    below "$(field "$csv" '^stripes,table-1.1-plane,fine,' rms_vs_llvmpipe)" 0.002 ||
        fail "the camera file's view departs"
    own=$(field "$csv" '^stripes,camera,fine,' rms_vs_truth)
    [ "$own" = "$(field "$csv" '^stripes,table-1.1-plane,fine,' rms_vs_truth)" ] ||
        fail "the scene's own camera, given as a file, sees another image"
    check_report "$out" 6
    ;;
glsl)
    "$qs" study "$plane" --glsl "$src/examples/minimal/stripes.frag" --views minified --modes fine,dual2 $small \
        -o "$out" || fail "exit $?"
    csv=$out/study.csv
    below "$(field "$csv" '^stripes.frag,minified,fine,' rms_vs_llvmpipe)" 0.002 || fail "fine departs from llvmpipe"
    # Minified stripes: the analytic width filters them, the quads' fwidth of a folded ramp does not.
    below "$(field "$csv" '^stripes.frag,minified,dual2,' rms_vs_truth)" \
        "$(field "$csv" '^stripes.frag,minified,fine,' rms_vs_truth)" ||
            fail "dual2 is not closer to the truth than fine"
    check_report "$out" 5
    ;;
stability)
    tiny="--views camera --modes fine --no-reference --no-derivative-maps --time 1000"
    "$qs" study "$plane" --shader dots_aa $tiny $small -o "$out/near" || fail "exit $?"
    "$qs" study "$plane" --shader dots_aa $tiny $small --offset 100000,100000,0 -o "$out/far" || fail "exit $?"
    "$qs" study "$plane" --shader float_env_probe $tiny $small -o "$out/probe" || fail "exit $?"
    grep -q ',100000 100000 0,1000$' "$out/far/views.csv" || fail "views.csv does not record the offset and the time"
    below "$(field "$out/near/stability.csv" '^dots_aa,camera,' rms_float_vs_double)" 1e-4 ||
        fail "float departs near the origin"
    below 0.01 "$(field "$out/far/stability.csv" '^dots_aa,camera,' rms_float_vs_double)" ||
        fail "float does not depart from double 100000 from the origin"
    below 0 "$(field "$out/far/stability.csv" '^dots_aa,camera,' over_1_255)" || fail "no pixel counted over 1/255"
    below 0 "$(field "$out/probe/stability.csv" '^float_env_probe,camera,' nan)" ||
        fail "the probe's NaNs are not marked"
    below 0 "$(field "$out/probe/stability.csv" '^float_env_probe,camera,' division_by_zero)" ||
        fail "the probe's divisions by zero are not marked"
    [ -s "$out/probe/images/float_env_probe-camera/undefined.png" ] || fail "no undefined-case mask"
    grep -q 'Undefined GLSL cases the colour depends on' "$out/probe/report.html" ||
        fail "the report says nothing of them"
    ;;
bench)
    "$qs" study --study "$src/bench/study.txt" -o "$out" --size 16 --truth 2 --repeat 1 --modes fine,step,ss2x2 \
        --no-reference --no-derivative-maps || fail "exit $?"
    [ "$(tail -n +2 "$out/study.csv" | wc -l)" -eq 39 ] || fail "expected 39 rows (13 cases x 3 modes)"
    [ "$(field "$out/study.csv" '^spots,camera,step,' variant)" = spots_step ] || fail "no spots row"
    cp "$src/docs/results.md" "$out/results.md"
    /usr/bin/python3 "$src/bench/results.py" "$out/no-build" "$out" "$out/results.md" > /dev/null 2>&1 ||
        fail "results.py failed"
    sed -n '/<!-- results:error -->/,/<!-- \/results -->/p' "$out/results.md" > "$out/error-table.md"
    grep -q '^| case | fine | step | ss2x2 | Pareto front |$' "$out/error-table.md" || fail "the error table's header"
    for row in "dots_aa magnified" "bricks_aa minified" "worley_tiles grazing" "halftone grazing" "spots camera"; do
        grep -q "^| $row | " "$out/error-table.md" || fail "the error table has no row '$row'"
    done
    ;;
refused)
    printf '%s\n' "# one good line, one bad" "plane.gltf --shader dots_aa" "plane.gltf --shader dots_aa --sharpness 3" \
        > "$out/bad-study.txt"
    expect=$src/tests/check/expect_exit.sh
    "$expect" 2 'name the shader with --shader NAME or --glsl FRAG' "$qs" study "$plane" -o "$out/a" &&
    "$expect" 2 "no view 'sideways'" "$qs" study "$plane" --shader dots_aa --views sideways -o "$out/b" &&
    "$expect" 2 "no mode 'ss3x3' for this shader" "$qs" study "$plane" --shader dots_aa --modes ss3x3 -o "$out/c" &&
    "$expect" 2 "no mode 'step'" "$qs" study "$plane" --shader dots_aa --modes step -o "$out/d" &&
    "$expect" 1 "unknown shader 'no_such_shader'" "$qs" study "$plane" --shader no_such_shader -o "$out/e" &&
    "$expect" 2 'exists and is not a folder' "$qs" study "$plane" --shader dots_aa -o "$plane" &&
    "$expect" 1 'no_such.gltf' "$qs" study "$src/no_such.gltf" --shader dots_aa -o "$out/f" &&
    "$expect" 2 'bad-study.txt:3: .*--sharpness' "$qs" study --study "$out/bad-study.txt" -o "$out/g" &&
    "$expect" 2 '--study: --shader goes on the file' "$qs" study --study "$out/bad-study.txt" --shader dots_aa \
        -o "$out/h" ||
        fail "not refused as expected"
    # An output over an input, and a link where the study makes a folder of its own.
    mkdir -p "$out/i" "$out/j" "$out/elsewhere" && ln -s "$out/elsewhere" "$out/j/images" &&
    printf '%s\n' "$plane --shader dots_aa" > "$out/i/study.csv" &&
    "$expect" 2 'study.csv: an input of this study' "$qs" study --study "$out/i/study.csv" -o "$out/i" &&
    "$expect" 1 'images: is a symbolic link' "$qs" study "$plane" --shader dots_aa --no-reference $small -o "$out/j" ||
        fail "outputs over inputs not refused"
    [ -z "$(ls -A "$out/elsewhere")" ] || fail "written through a link"
    ls "$out"/*/report.html 2> /dev/null && fail "a refused study wrote a report"
    ;;
expressions)
    # A user's .frag whose fwidth's argument is a local of main's.
    printf '%s\n' '#version 130' 'in vec2 st;' 'out vec4 colour;' 'void main() {' '    float ramp = 8.0 * st.s;' \
        '    float w = fwidth(ramp);' '    colour = vec4(vec3(smoothstep(0.5 - w, 0.5 + w, fract(ramp))), 1.0);' '}' \
        > "$out/ramp.frag"
    tiny="--views camera,grazing --modes fine --no-reference"
    "$qs" study "$plane" --glsl "$out/ramp.frag" $tiny $small -o "$out/inputs" || fail "exit $?"
    "$qs" study "$plane" --glsl "$out/ramp.frag" $tiny $small --derivatives-of ramp --derivatives-of "st * 8.0" \
        -o "$out/named" || fail "exit $?"
    d=$out/named/derivatives.csv
    [ "$(tail -n +2 "$d" | wc -l)" -eq 18 ] || fail "expected 18 derivative rows (2 views x 3 maps x 3 rules)"
    # The named maps replace the inputs'; ramp = 8 st.s, the same map as (st * 8.0).x, 8 times st.s's.
    grep -q ',st[.]s,' "$d" && fail "the inputs are mapped beside the named expressions"
    for view in camera grazing; do
        s=$(field "$out/inputs/derivatives.csv" "^ramp.frag,$view,st[.]s,fine," analytic_rms)
        r=$(field "$d" "^ramp.frag,$view,ramp,fine," analytic_rms)
        x=$(field "$d" "^ramp.frag,$view,[(]st [*] 8[.]0[)][.]x,fine," analytic_rms)
        awk -v s="$s" -v r="$r" -v x="$x" 'BEGIN { exit !(s > 0 && r == x && (r / s - 8) ^ 2 < 1e-10) }' ||
            fail "$view: ramp's derivatives ($r, $x) are not 8 times st.s's ($s)"
        [ "$(field "$d" "^ramp.frag,$view,ramp,coarse-upper," covered)" = \
            "$(field "$out/inputs/derivatives.csv" "^ramp.frag,$view,st[.]s,coarse-upper," covered)" ] ||
            fail "$view: the expression does not cover the pixels the inputs do"
    done
    below "$(field "$d" '^ramp.frag,camera,ramp,coarse-lower,' max_dx)" 1e-5 ||
        fail "camera: coarse dFdx(ramp) is not exact"
    below 1e-4 "$(field "$d" '^ramp.frag,grazing,ramp,coarse-upper,' rms_dx)" ||
        fail "grazing: coarse dFdx(ramp) is exact"
    [ -s "$out/named/images/ramp.frag-grazing/d-expression-2.y-fine-heat.png" ] || fail "no map of (st * 8.0).y"
    grep -q '(st [*] 8.0).y' "$out/named/report.html" || fail "the report does not name the expression"
    check_report "$out/named" 20
    # A catalogue shader's own GLSL: dots_aa's aastep argument.
    "$qs" study "$plane" --shader dots_aa --views camera --modes fine --no-reference $small \
        --derivatives-of "length(fract(5.0 * st) - 0.5)" -o "$out/catalogue" || fail "exit $?"
    below 0 "$(field "$out/catalogue/derivatives.csv" '^dots_aa,camera,length' analytic_rms)" ||
        fail "no map of dots_aa's aastep argument"
    # Anything but one float expression is refused, naming the option, before anything is written.
    expect=$src/tests/check/expect_exit.sh
    named="study $plane --glsl $out/ramp.frag --views camera --modes fine --no-reference $small -o $out/refused"
    "$expect" 2 "--derivatives-of \"ramp; colour = vec4.1.0.\": error: ';' at offset 4" \
        "$qs" $named --derivatives-of 'ramp; colour = vec4(1.0)' &&
    "$expect" 2 "error: ';' at offset 7" "$qs" $named --derivatives-of '(ramp) ; } void f() { (ramp)' &&
    "$expect" 2 'a comment' "$qs" $named --derivatives-of 'ramp /* x */' &&
    "$expect" 2 "--derivatives-of \"rmp\": error: 'rmp': undeclared identifier" "$qs" $named --derivatives-of rmp &&
    "$expect" 2 'dFdx and dFdy take a float or a float vector' "$qs" $named --derivatives-of 'int(ramp)' &&
    "$expect" 2 '--derivatives-of and --no-derivative-maps' "$qs" $named --derivatives-of ramp --no-derivative-maps ||
        fail "bad expressions not refused"
    [ -e "$out/refused" ] && fail "a refused study made its folder"
    ;;
frames)
    scene=$src/scenes/assets/gltf/animation.gltf
    tiny="--modes fine --no-reference --no-derivative-maps"
    "$qs" study "$scene" --shader dots_aa --frames 0,30 $tiny $small -o "$out/camera" || fail "exit $?"
    v=$out/camera/views.csv
    [ "$(tail -n +2 "$v" | wc -l)" -eq 2 ] || fail "expected 2 views (the camera at 2 frames)"
    # (views.csv's truth holds a comma: the time is read as the line's last field.)
    grep -q '^dots_aa,frame-30,.*,1$' "$v" || fail "frame 30 is not at time 1 (30 fps)"
    grep -q '^dots_aa,frame-0,.*,0$' "$v" || fail "frame 0 is not at time 0"
    cmp -s "$out/camera/images/dots_aa-frame-0/truth.png" "$out/camera/images/dots_aa-frame-30/truth.png" &&
        fail "the animation did not move between frames 0 and 30"
    # Each generated view at each frame of a range, at another rate.
    "$qs" study "$scene" --shader dots_aa --frames 0:1 --fps 2 --views camera,magnified $tiny $small \
        -o "$out/views" || fail "exit $?"
    [ "$(tail -n +2 "$out/views/study.csv" | wc -l)" -eq 4 ] || fail "expected 4 rows (2 views x 2 frames)"
    grep -q '^dots_aa,magnified-frame-1,.*,0[.]5$' "$out/views/views.csv" ||
        fail "magnified at frame 1 is not at time 0.5"
    expect=$src/tests/check/expect_exit.sh
    "$expect" 2 '--frames: 3:1: B must not be less than A' "$qs" study "$scene" --shader dots_aa --frames 3:1 \
        -o "$out/a" &&
    "$expect" 2 "--frames: 'x' is not a frame" "$qs" study "$scene" --shader dots_aa --frames 0,x -o "$out/b" &&
    "$expect" 2 '--frames: frame 2 is named twice' "$qs" study "$scene" --shader dots_aa --frames 0:3,2 \
        -o "$out/c" &&
    "$expect" 2 '--frames and --time' "$qs" study "$scene" --shader dots_aa --frames 0 --time 1 -o "$out/d" ||
        fail "bad frames not refused"
    for o in a b c d; do [ -e "$out/$o" ] && fail "a refused study made its folder $o"; done
    ;;
memory)
    expect=$src/tests/check/expect_exit.sh
    "$expect" 1 'study: the ss8x8 mode .*needs .*, more than the 64.0 MiB available .--memory-limit' \
        "$qs" study "$plane" --shader dots_aa --size 512 --views camera --memory-limit 64M -o "$out/a" &&
    "$expect" 1 'study: the truth .*needs .*, more than the 64.0 MiB available' \
        "$qs" study "$plane" --shader dots_aa --views camera --modes fine --no-reference --size 512 --truth 64 \
        --memory-limit 64M -o "$out/b" &&
    "$expect" 2 '--size times --truth is over 32768 pixels on a side' \
        "$qs" study "$plane" --shader dots_aa --size 1024 --truth 64 -o "$out/e" &&
    "$expect" 2 '--memory-limit' "$qs" study "$plane" --shader dots_aa --memory-limit lots -o "$out/c" ||
        fail "not refused as expected"
    for o in a b c e; do [ -e "$out/$o" ] && fail "a refused study made its folder $o"; done
    "$qs" study "$plane" --shader dots_aa --views camera --modes fine,ss2x2 $small --memory-limit 2G -o "$out/d" ||
        fail "a study within its limit: exit $?"
    ;;
*) fail "unknown case" ;;
esac
echo "study_test.sh ($case): passed"
