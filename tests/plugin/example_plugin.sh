#!/bin/sh
# The installed package from a clean prefix, as a user gets it: examples/my-shader configures and
# builds against it with find_package(quadshade), `quadshade render --plugin` draws its shader,
# `quadshade shaders --plugin` lists it and exports its GLSL, and OSMesa running that GLSL draws the
# same picture (within 1/255: the example is a derivative shader under llvmpipe's fine rule).
# Usage: example_plugin.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -eu
src=$1 build=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$src/examples/my-shader" -B "$work/my-build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/my-build" > "$work/build.log"

bin=$work/prefix/bin
plugin=$work/my-build/libmy_shaders.so
scene=$src/scenes/assets/table-1.1-plane.gltf
"$bin/quadshade" shaders --plugin "$plugin" | grep -q '^ *my_stripes '
"$bin/quadshade" render "$scene" --plugin "$plugin" --shader my_stripes --size 160x120 -o "$work/stripes.exr"
"$bin/quadshade" render "$scene" --plugin "$plugin" --shader my_stripes --size 160x120 -o "$work/stripes.png"

# Without the plugin the shader is unknown (exit 1, naming it).
if "$bin/quadshade" render "$scene" --shader my_stripes -o "$work/none.png" 2> "$work/unknown.txt"; then
    echo "my_stripes rendered without its plugin" >&2; exit 1
fi
grep -q "my_stripes" "$work/unknown.txt"
# The same shaders from a second file: refused, naming the shader and where it came from first.
cp "$plugin" "$work/copy.so"
if "$bin/quadshade" shaders --plugin "$plugin" --plugin "$work/copy.so" > /dev/null 2> "$work/twice.txt"; then
    echo "a second plugin redefining my_stripes was accepted" >&2; exit 1
fi
grep -q "my_stripes' is already defined by" "$work/twice.txt"
# Not a plugin: refused with the file named.
if "$bin/quadshade" shaders --plugin "$scene" > /dev/null 2> "$work/bad.txt"; then
    echo "a glTF file was accepted as a plugin" >&2; exit 1
fi
grep -q "table-1.1-plane.gltf: cannot load the plugin" "$work/bad.txt"

if [ -x "$bin/quadshade-reference" ]; then
    "$bin/quadshade" shaders --plugin "$plugin" --export-glsl "$work/glsl" > /dev/null
    cmp "$work/glsl/my_stripes.frag" "$src/examples/my-shader/my_stripes.frag" > /dev/null 2>&1 &&
        { echo "exported GLSL lacks its #version line" >&2; exit 1; }
    "$bin/quadshade-reference" "$scene" --glsl "$work/glsl" --shader my_stripes --size 160x120 -o "$work/osmesa.exr"
    "$bin/quadshade" compare "$work/stripes.exr" "$work/osmesa.exr" --fail 1
fi
echo "examples/my-shader: built against the installed package, rendered, and matched OSMesa"
