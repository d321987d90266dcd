#!/bin/sh
# check_memory.sh QUADSHADE PLUGIN SCENES WORK: `quadshade check` on a 32768x32768 scene with
# --memory-limit 1G stops with a message naming the scene, its size and the memory it needs,
# before the reference renders anything, and leaves no reference image, log or report behind.
set -u
quadshade=$1 plugin=$2 scenes=$3 work=$4
rm -rf "$work" && mkdir -p "$work/huge" || exit 1
cd "$work" || exit 1
fail() { echo "check_memory.sh: $*" >&2; exit 1; }
# The plane at 500x500, its size (two lines of the scene's extras) made 32768x32768.
sed 's/^\( *\)500,$/\132768,/; s/^\( *\)500$/\132768/' "$scenes/table-1.1-plane.gltf" >huge/plane.gltf || exit 1
cp "$scenes/table-1.1-plane.bin" huge/ && cp -r "$scenes/textures" huge/ || exit 1
grep -q 32768 huge/plane.gltf || fail "the scene's size was not found to change"
"$quadshade" check stripes --plugin "$plugin" --scenes huge --memory-limit 1G -o out >out.txt 2>&1
status=$?
cat out.txt
[ "$status" -eq 1 ] || fail "exit $status, expected 1"
grep -Eq "checking stripes on .*plane.gltf \(32768x32768\) needs [0-9.]+ GiB, more than the 1.0 GiB available" \
    out.txt || fail "the message does not name the case, its size and the memory it needs"
[ ! -e out/report.csv ] || fail "a report was written"
[ -z "$(find out -name 'reference-*' -o -name '.*' | head -1)" ] || fail "a reference image, log or scratch folder was left"
echo "check_memory.sh: refused by its size, nothing left"
