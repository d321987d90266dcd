#!/bin/sh
# writing_shaders_test.sh SOURCE_DIR PREFIX WORK_DIR: docs/writing-shaders.md's code blocks as a
# plugin (tests/docs/extract_examples.py), built against the package installed in PREFIX, and every
# shader they register checked against OSMesa on the Table 1.1 plane: the page's examples compile
# and are right as printed.
set -eu
src=$1 prefix=$2 work=$3
rm -rf "$work"
mkdir -p "$work/plugin"
names=$(python3 "$src/tests/docs/extract_examples.py" "$src/docs/writing-shaders.md" "$work/plugin" examples.cpp)
glsl=$(cd "$work/plugin" && ls *.frag *.vert 2> /dev/null | tr '\n' ' ')
cat > "$work/plugin/CMakeLists.txt" << CMAKE
cmake_minimum_required(VERSION 3.25)
project(writing_shaders LANGUAGES CXX)
find_package(quadshade REQUIRED)
quadshade_add_shader_plugin(writing_shaders SOURCES examples.cpp GLSL $glsl)
CMAKE
cmake -S "$work/plugin" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log" 2>&1 || { cat "$work/build.log" >&2; exit 1; }
plugin=$work/build/libwriting_shaders.so
for name in $names; do
    "$prefix/bin/quadshade" shaders --plugin "$plugin" | grep -q "^ *$name " ||
        { echo "docs/writing-shaders.md: $name is not registered" >&2; exit 1; }
done
# shellcheck disable=SC2086
"$prefix/bin/quadshade" check $names --plugin "$plugin" --scenes "$prefix/share/quadshade/scenes/table-1.1-plane.gltf" \
    --size 128x96 -o "$work/check"
