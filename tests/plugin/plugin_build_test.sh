#!/bin/sh
# plugin_build_test.sh SOURCE_DIR PREFIX WORK_DIR: what quadshade_add_shader_plugin does with a
# plugin's GLSL and its optimisation, on a copy of examples/minimal built against PREFIX:
#  - an edit of the .frag alone reaches the plugin's folder with the next build, and quadshade
#    exports the edited text;
#  - a Debug build (unoptimised on purpose) loads with a warning that names the plugin.
set -eu
src=$1 prefix=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cp -r "$src/examples/minimal" "$work/source"
cmake -S "$work/source" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
cmp "$work/source/stripes.frag" "$work/build/stripes.frag"

sed 's/8\.0 \* (st\.x + st\.y)/6.0 * (st.x - st.y)/' "$work/source/stripes.frag" > "$work/edited.frag"
if cmp -s "$work/edited.frag" "$work/source/stripes.frag"; then echo "the edit changed nothing" >&2; exit 1; fi
cp "$work/edited.frag" "$work/source/stripes.frag"
cmake --build "$work/build" > "$work/rebuild.log"
cmp "$work/source/stripes.frag" "$work/build/stripes.frag" ||
    { echo "the edited stripes.frag did not reach the build folder" >&2; exit 1; }
"$prefix/bin/quadshade" shaders --plugin "$work/build/libminimal.so" --export-glsl "$work/glsl" > /dev/null
grep -q "6.0 \* (st.x - st.y)" "$work/glsl/stripes.frag" ||
    { echo "quadshade exported the old stripes.frag" >&2; exit 1; }

cmake -S "$work/source" -B "$work/debug" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Debug > "$work/debug-configure.log"
cmake --build "$work/debug" > "$work/debug-build.log"
"$prefix/bin/quadshade" shaders --plugin "$work/debug/libminimal.so" > /dev/null 2> "$work/debug-load.txt"
grep -q "libminimal.so.*without optimisation" "$work/debug-load.txt" ||
    { echo "no warning for an unoptimised plugin:" >&2; cat "$work/debug-load.txt" >&2; exit 1; }
echo "plugins: an edited .frag reaches the build; an unoptimised plugin is warned about"
