#!/bin/sh
# concurrent_check.sh QUADSHADE PLUGIN SCENES WORK: two `quadshade check` runs sharing one output
# folder (-o) at once, each with two cases in flight. Each must compare its renders with its own
# references (a run reading the other's would fail cases), and the shared folder must end with a
# whole report.csv and no reference image, log or scratch folder left.
set -u
quadshade=$1 plugin=$2 scenes=$3 work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
fail() { echo "concurrent_check.sh: $*" >&2; exit 1; }
run() {
    "$quadshade" check stripes --plugin "$plugin" --scenes "$scenes" --jobs 2 -o shared >"run$1.txt" 2>&1
    echo $? >"status$1"
}
run 1 &
first=$!
run 2 &
second=$!
wait "$first" "$second"
for k in 1 2; do
    cat "run$k.txt"
    [ "$(cat "status$k")" -eq 0 ] || fail "run $k: exit $(cat "status$k")"
    grep -Eq "quadshade check: [0-9]+ cases .* 0 failed" "run$k.txt" || fail "run $k failed a case"
done
cases=$(sed -n 's/^quadshade check: \([0-9]*\) cases.*/\1/p' run1.txt)
[ "$(wc -l <shared/report.csv)" -eq $((cases + 1)) ] || fail "report.csv is not one header and $cases rows"
[ "$(grep -c ',ok$' shared/report.csv)" -eq "$cases" ] || fail "report.csv's rows are not whole"
[ -z "$(find shared -name 'reference-*' -o -name '.*' | head -1)" ] ||
    fail "a reference image, log or scratch folder was left"
echo "concurrent_check.sh: both runs passed, report.csv whole"
