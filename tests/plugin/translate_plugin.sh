#!/bin/sh
# A user's GLSL turned into C++ and compiled, from the installed package: `quadshade translate`
# writes examples/minimal's GLSL as a translation whose CMakeLists.txt builds against the
# package installed in PREFIX, and the plugin draws the interpreter's picture to the bit; `render --compile` compiles
# the same translation into the plugin cache once, uses the cached plugin without --compile, and
# runs the interpreter with one warning where the cache cannot be used.
# Usage: translate_plugin.sh SOURCE_DIR PREFIX WORK_DIR
set -eu
src=$1 prefix=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
bin=$prefix/bin
frag=$src/examples/minimal/stripes.frag
scene=$prefix/share/quadshade/scenes/table-1.1-plane.gltf
size="--size 96x64"

"$bin/quadshade" translate "$frag" -o "$work/translation" > /dev/null
cmake -S "$work/translation" -B "$work/translation/build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log"
cmake --build "$work/translation/build" > "$work/build.log"
"$bin/quadshade" render "$scene" $size --glsl "$frag" -o "$work/interpreted.png" 2> /dev/null
"$bin/quadshade" render "$scene" $size --plugin "$work/translation/build/libstripes.so" --shader stripes \
    -o "$work/translated.png" 2> /dev/null
# The same pixels (the files' metadata name the shaders differently).
same() { "$bin/quadshade" compare "$1" "$2" --fail 0 --max-failing 0 > /dev/null; }
same "$work/interpreted.png" "$work/translated.png"

# Compiled on request, then from the cache.
XDG_CACHE_HOME=$work/cache "$bin/quadshade" render "$scene" $size --glsl "$frag" --compile \
    -o "$work/compiled.png" 2> "$work/compile.txt"
grep -q "compiled stripes.frag in" "$work/compile.txt"
same "$work/interpreted.png" "$work/compiled.png"
XDG_CACHE_HOME=$work/cache "$bin/quadshade" render "$scene" $size --glsl "$frag" \
    -o "$work/cached.png" 2> "$work/cached.txt"
if grep -q "compil" "$work/cached.txt"; then echo "the cached plugin was compiled again" >&2; exit 1; fi
same "$work/interpreted.png" "$work/cached.png"
[ "$(ls "$work/cache/quadshade/plugins" | wc -l)" = 1 ]

# A cache that cannot be written: the interpreter's picture, and one warning.
touch "$work/not-a-folder"
XDG_CACHE_HOME=$work/not-a-folder "$bin/quadshade" render "$scene" $size --glsl "$frag" --compile \
    -o "$work/fallback.png" 2> "$work/fallback.txt"
[ "$(grep -c "warning" "$work/fallback.txt")" = 1 ]
same "$work/interpreted.png" "$work/fallback.png"
