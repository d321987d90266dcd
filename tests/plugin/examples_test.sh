#!/bin/sh
# examples_test.sh SOURCE_DIR PREFIX WORK_DIR: each plugin of examples/ configured and built with
# the README's commands (no CMAKE_BUILD_TYPE) against the package installed in PREFIX, loaded by
# quadshade without a warning (so built optimised), rendered, and checked against OSMesa on the
# Table 1.1 plane; then the refusals: a shader unknown without its plugin, a plugin loaded twice,
# a file that is no plugin.
set -eu
src=$1 prefix=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
bin=$prefix/bin
scene=$prefix/share/quadshade/scenes/table-1.1-plane.gltf

build_example() {  # NAME: builds examples/NAME into WORK/NAME-build as the README says
    cmake -S "$src/examples/$1" -B "$work/$1-build" -DCMAKE_PREFIX_PATH="$prefix" > "$work/$1-configure.log"
    grep -q "plugin .* is built with the Release flags" "$work/$1-configure.log" ||
        { echo "examples/$1: configured without saying it builds with the Release flags" >&2; exit 1; }
    cmake --build "$work/$1-build" > "$work/$1-build.log"
}

build_example minimal
build_example uniforms-texture
minimal=$work/minimal-build/libminimal.so
tinted=$work/uniforms-texture-build/libtinted.so

for plugin in "$minimal" "$tinted"; do
    "$bin/quadshade" shaders --plugin "$plugin" > "$work/listing.txt" 2> "$work/listing-stderr.txt"
    if [ -s "$work/listing-stderr.txt" ]; then
        echo "loading $plugin printed:" >&2; cat "$work/listing-stderr.txt" >&2; exit 1
    fi
done
"$bin/quadshade" shaders --plugin "$minimal" | grep -q '^ *stripes '
"$bin/quadshade" render "$scene" --plugin "$minimal" --shader stripes --size 160x120 -o "$work/stripes.png"
"$bin/quadshade" render "$scene" --plugin "$tinted" --shader tinted_texture --uniform uTint=0.2,0.6,1 \
    --size 160x120 -o "$work/tinted.png"

if [ -x "$bin/quadshade-reference" ]; then
    "$bin/quadshade" check stripes --plugin "$minimal" --scenes "$scene" --size 160x120 -o "$work/check-minimal" \
        > "$work/check-minimal.txt" || { cat "$work/check-minimal.txt" >&2; exit 1; }
    "$bin/quadshade" check tinted_texture --plugin "$tinted" --scenes "$scene" --size 160x120 -o "$work/check-tinted" \
        > "$work/check-tinted.txt" || { cat "$work/check-tinted.txt" >&2; exit 1; }
fi

# Without the plugin the shader is unknown (exit 1, naming it).
if "$bin/quadshade" render "$scene" --shader stripes -o "$work/none.png" 2> "$work/unknown.txt"; then
    echo "stripes rendered without its plugin" >&2; exit 1
fi
grep -q "stripes" "$work/unknown.txt"
# The same shaders from a second file: refused, naming the shader and where it came from first.
cp "$minimal" "$work/copy.so"
if "$bin/quadshade" shaders --plugin "$minimal" --plugin "$work/copy.so" > /dev/null 2> "$work/twice.txt"; then
    echo "a second plugin redefining stripes was accepted" >&2; exit 1
fi
grep -q "stripes' is already defined by" "$work/twice.txt"
# Not a plugin: refused with the file named.
if "$bin/quadshade" shaders --plugin "$scene" > /dev/null 2> "$work/bad.txt"; then
    echo "a glTF file was accepted as a plugin" >&2; exit 1
fi
grep -q "table-1.1-plane.gltf: cannot load the plugin" "$work/bad.txt"
echo "examples/: built against the installed package as the README says, optimised, and matched OSMesa"
