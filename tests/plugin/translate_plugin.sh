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
if grep -q "warning" "$work/compile.txt"; then cat "$work/compile.txt" >&2; exit 1; fi  # the plugin loads
same "$work/interpreted.png" "$work/compiled.png"
XDG_CACHE_HOME=$work/cache "$bin/quadshade" render "$scene" $size --glsl "$frag" \
    -o "$work/cached.png" 2> "$work/cached.txt"
if grep -q "compil\|warning" "$work/cached.txt"; then cat "$work/cached.txt" >&2; exit 1; fi  # loaded, not compiled again
same "$work/interpreted.png" "$work/cached.png"
[ "$(ls "$work/cache/quadshade/plugins" | wc -l)" = 1 ]
# The plugin holds what that render shades (llvmpipe's rule, float): a render by softpipe's rule is
# the interpreter's, without compiling or a warning.
XDG_CACHE_HOME=$work/cache "$bin/quadshade" render "$scene" $size --glsl "$frag" --derivatives coarse-lower \
    -o "$work/coarse.png" 2> "$work/coarse.txt"
if grep -q "compil\|warning" "$work/coarse.txt"; then cat "$work/coarse.txt" >&2; exit 1; fi
XDG_CACHE_HOME=$work/no-cache "$bin/quadshade" render "$scene" $size --glsl "$frag" --derivatives coarse-lower \
    -o "$work/coarse-interpreted.png" 2> /dev/null
same "$work/coarse-interpreted.png" "$work/coarse.png"

# A material naming the GLSL (extras.glsl) follows the same rule: render --compile compiles it
# into an empty cache, and a render without it finds it there; the interpreter's picture each time.
mkdir -p "$work/material"
cp -r "$frag" "$(dirname "$scene")"/table-1.1-plane.bin "$(dirname "$scene")"/textures "$work/material/"
sed 's/"shader": *"perlin"/"glsl": "stripes.frag"/' "$scene" > "$work/material/plane.gltf"
grep -q '"glsl": "stripes.frag"' "$work/material/plane.gltf"
XDG_CACHE_HOME=$work/material-cache "$bin/quadshade" render "$work/material/plane.gltf" $size --compile \
    -o "$work/material/compiled.png" 2> "$work/material/compile.txt"
grep -q "compiled stripes.frag in" "$work/material/compile.txt"
XDG_CACHE_HOME=$work/material-cache "$bin/quadshade" render "$work/material/plane.gltf" $size \
    -o "$work/material/cached.png" 2> "$work/material/cached.txt"
if grep -q "compil\|warning" "$work/material/cached.txt"; then cat "$work/material/cached.txt" >&2; exit 1; fi
XDG_CACHE_HOME=$work/no-cache "$bin/quadshade" render "$work/material/plane.gltf" $size \
    -o "$work/material/interpreted.png" 2> /dev/null
same "$work/material/interpreted.png" "$work/material/compiled.png"
same "$work/material/interpreted.png" "$work/material/cached.png"

# A cache that cannot be written: the interpreter's picture, and one warning.
touch "$work/not-a-folder"
XDG_CACHE_HOME=$work/not-a-folder "$bin/quadshade" render "$scene" $size --glsl "$frag" --compile \
    -o "$work/fallback.png" 2> "$work/fallback.txt"
[ "$(grep -c "warning" "$work/fallback.txt")" = 1 ]
same "$work/interpreted.png" "$work/fallback.png"

# gallery --glsl and test's glsl cases follow render's rule: the cached plugin, --compile where the
# cache lacks it. A cache whose plugin is broken shows that they looked there: one warning, and
# the interpreter's picture.
cp -r "$work/cache" "$work/broken-cache"
for lib in "$work"/broken-cache/quadshade/plugins/*/lib*.so; do : > "$lib"; done
mkdir -p "$work/suite/expected"
cp "$frag" "$work/suite/stripes.frag"
cp "$work/interpreted.png" "$work/suite/expected/stripes.png"
printf '{"cases": [{"name": "stripes", "scene": "%s", "glsl": "stripes.frag", "size": "96x64"}]}\n' "$scene" \
    > "$work/suite/suite.json"
for cache in cache broken-cache; do
    XDG_CACHE_HOME=$work/$cache "$bin/quadshade" test "$work/suite/suite.json" --allow-outside-paths --compile \
        > /dev/null 2> "$work/suite-$cache.txt"
    XDG_CACHE_HOME=$work/$cache "$bin/quadshade" gallery "$work/gallery-$cache" --glsl "$frag" --compile \
        --scenes "$scene" --size 32 > /dev/null 2> "$work/gallery-$cache.txt"
    [ -f "$work/gallery-$cache/glsl.png" ]
done
for run in suite gallery; do
    if grep -q "compil\|warning" "$work/$run-cache.txt"; then cat "$work/$run-cache.txt" >&2; exit 1; fi
    [ "$(grep -c "cached plugin does not load" "$work/$run-broken-cache.txt")" = 1 ]
done
