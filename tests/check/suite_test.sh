#!/bin/sh
# suite_test.sh QUADSHADE SOURCE_DIR WORK: `quadshade test` end to end on a small suite of its own:
# blessing, passing, a failure (exit 3, the actual image and the difference kept beside the
# expected one, JUnit and HTML reports saying so), shards merged into what one process reports,
# a missing shard and a bad suite file refused.
set -u
quadshade=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
fail() { echo "suite_test.sh: $*" >&2; exit 1; }
expect() {  # expect CODE COMMAND...: runs it, its output in out.txt
    code=$1; shift
    "$@" >out.txt 2>&1; status=$?
    cat out.txt
    [ "$status" -eq "$code" ] || fail "exit $status, expected $code: $*"
}
plane=$source/scenes/assets/table-1.1-plane.gltf figure=$source/scenes/assets/figure-1.1.gltf
# The suite names the repository's scenes by absolute path: outside its folder, so allowed.
qt() { "$quadshade" test --allow-outside-paths "$@"; }
cat >suite.json <<EOF
{"name": "mechanics", "defaults": {"scene": "$plane", "size": "40x24"},
 "cases": [{"name": "perlin", "shader": "perlin"}, {"name": "dots", "shader": "dots"},
           {"name": "wave", "shader": "wave_aa", "time": 0.5}, {"name": "figure", "scene": "$figure", "size": "79x25"},
           {"name": "checker", "shader": "checker", "tolerance": {"fail": 0, "warn": 0}}]}
EOF
expect 0 qt suite.json --update --jobs 2
grep -q "5 cases, 0 passed, 0 warned, 0 failed, 5 updated" out.txt || fail "--update did not bless 5 cases"
[ -f expected/perlin.png ] && [ -f expected/figure.png ] || fail "no expected images"
expect 0 qt suite.json --junit pass.xml --html pass-html
grep -q "5 cases, 5 passed" out.txt || fail "the blessed suite does not pass"
grep -Eq '^\[ ?[0-9]/5\] PASS' out.txt || fail "no progress lines"
# A report written over the suite itself is refused, and the suite is left as it was.
cp suite.json suite.before
expect 2 qt suite.json --junit suite.json
grep -q "is an input of this command" out.txt && cmp -s suite.json suite.before || fail "--junit over the suite file"
expect 2 qt suite.json --report ./suite.json
cmp -s suite.json suite.before || fail "--report over the suite file"

# A regression: dots' expected image is perlin's.
cp expected/perlin.png expected/dots.png
expect 3 qt suite.json --junit fail.xml --html fail-html
grep -q "FAIL dots" out.txt || fail "the summary does not name the failure"
[ -f expected/dots.actual.png ] && [ -f expected/dots.diff.png ] || fail "no actual and diff image beside the expected one"
[ ! -f expected/perlin.actual.png ] || fail "a passing case left an actual image"
grep -q 'img src="images/dots.diff.png"' fail-html/index.html && [ -f fail-html/images/dots.actual.png ] ||
    fail "the HTML report lacks the failure's images"
python3 - <<'EOF' || fail "JUnit XML"
import xml.etree.ElementTree as ET
for name, failures in (("pass.xml", []), ("fail.xml", ["dots"])):
    suite = ET.parse(name).getroot().find("testsuite")
    cases = suite.findall("testcase")
    assert [c.get("name") for c in cases] == ["perlin", "dots", "wave", "figure", "checker"], name
    assert [c.get("name") for c in cases if c.find("failure") is not None] == failures, name
    assert suite.get("failures") == str(len(failures)), name
EOF

# Shards: 1/3, 2/3 and 3/3 in separate processes, merged, report what one process reports.
for k in 1 2 3; do
    qt suite.json --shard $k/3 --report shard$k.json --jobs 1 >shard$k.txt 2>&1
    [ $? -eq $((k == 2 ? 3 : 0)) ] || { cat shard$k.txt; fail "shard $k/3's exit"; }  # dots is case 1: shard 2
done
grep -q "shard 1/3: 2 cases" shard1.txt || fail "shard 1/3 does not run cases 0 and 3"
expect 3 qt --merge shard3.json shard1.json shard2.json --junit merged.xml --html merged-html
grep -q "mechanics: 5 cases, 4 passed, 0 warned, 1 failed" out.txt || fail "the merged summary"
python3 - <<'EOF' || fail "the merged JUnit report is not the single run's"
import xml.etree.ElementTree as ET
def cases(name):
    return [(c.get("name"), c.find("failure") is not None and c.find("failure").get("message"))
            for c in ET.parse(name).getroot().iter("testcase")]
assert cases("merged.xml") == cases("fail.xml"), (cases("merged.xml"), cases("fail.xml"))
EOF
expect 1 qt --merge shard1.json shard3.json
grep -q "lack shard 2 of 3" out.txt || fail "a missing shard is not named"
expect 1 qt --merge shard1.json shard1.json shard2.json
grep -q "shard 1 is also" out.txt || fail "a shard given twice is not refused"

# Re-blessed, the failure's files go.
qt suite.json --update >/dev/null 2>&1 || fail "--update"
[ ! -f expected/dots.actual.png ] && [ ! -f expected/dots.diff.png ] || fail "stale actual and diff images left"

# Bad suites are refused with the file and the field.
printf '{"cases": [{"name": "a", "scene": "x.gltf", "sise": "4x4"}]}' >bad.json
expect 1 qt bad.json
grep -q "bad.json: cases\[0\].sise: unknown field" out.txt || fail "an unknown field is not named"
printf '{"cases": [{"name": "a", "scene": "%s", "tolerance": {"fail": -1}}]}' "$plane" >bad.json
expect 1 qt bad.json
grep -q "cases\[0\].tolerance.fail: expected a number within" out.txt || fail "a negative tolerance is not refused"
expect 2 qt suite.json --shard 4/3
echo "suite_test.sh: all passed"
