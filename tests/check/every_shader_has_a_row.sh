#!/bin/sh
# every_shader_has_a_row.sh QUADSHADE BENCH ARGS...: runs the bench program BENCH with ARGS and
# passes when it exits 0 and prints a table row ("| name |") for every shader that `QUADSHADE
# shaders` lists.
quadshade=$1
shift
out=$("$@") || { echo "every_shader_has_a_row.sh: $1 exited $?" >&2; exit 1; }
names=$("$quadshade" shaders | awk '/^  [a-z]/ { print $1 }') || exit 1
[ -n "$names" ] || { echo "every_shader_has_a_row.sh: no shaders listed" >&2; exit 1; }
missing=0
for name in $names; do
    if ! printf '%s\n' "$out" | grep -q "^| $name |"; then
        echo "every_shader_has_a_row.sh: no row for $name" >&2
        missing=1
    fi
done
exit $missing
