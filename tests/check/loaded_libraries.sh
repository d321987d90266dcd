#!/bin/sh
# loaded_libraries.sh QUADSHADE SOURCE_DIR WORK MODULE_DIR_FROM_BIN: each command loads the outside
# libraries it uses and no others, as the dynamic loader reports them (LD_DEBUG=files): `--help`
# and `shaders` load neither OpenImageIO, Embree nor OSMesa; a rasterized render to PNG loads none
# of them (libpng is linked), one to OpenEXR loads OpenImageIO and not Embree; a ray-cast one loads
# Embree (where it is built). A module that cannot be loaded is named, with its library, in the
# message of a render that needs it (exit 1, no output), while --help and a render to PNG still run
# without it.
set -eu
quadshade=$1 source=$2 work=$3 modules=$4
rm -rf "$work"
mkdir -p "$work"
plane=$source/scenes/assets/table-1.1-plane.gltf

# The objects a command loads, one file name a line.
loaded() {
    LD_DEBUG=files "$@" 2>&1 >/dev/null | sed -n 's/.*file=\([^ ]*\) *\[.*/\1/p' | sort -u
}
refuse() {  # refuse WHAT PATTERN LIST: fails when LIST names a file matching PATTERN
    if printf '%s\n' "$3" | grep -Eq "$2"; then
        echo "loaded_libraries.sh: $1 loads $(printf '%s\n' "$3" | grep -E "$2" | head -1)" >&2
        exit 1
    fi
}
require() {
    if ! printf '%s\n' "$3" | grep -Eq "$2"; then
        echo "loaded_libraries.sh: $1 does not load $2" >&2
        exit 1
    fi
}
outside='libOpenImageIO|libembree|libOSMesa|libquadshade-'

for args in "--help" "shaders" "render --help"; do
    # shellcheck disable=SC2086
    refuse "quadshade $args" "$outside" "$(loaded "$quadshade" $args)"
done
raster=$(loaded "$quadshade" render "$plane" --size 16x16 -o "$work/raster.png")
refuse "a rasterized render to PNG" "$outside" "$raster"
require "a rasterized render to PNG" 'libpng' "$raster"
exr=$(loaded "$quadshade" render "$plane" --size 16x16 -o "$work/raster.exr")
require "a rasterized render to OpenEXR" 'libquadshade-openimageio' "$exr"
require "a rasterized render to OpenEXR" 'libOpenImageIO' "$exr"
refuse "a rasterized render" 'libembree|libOSMesa|libquadshade-embree' "$exr"
if [ -e "$(dirname "$quadshade")/$modules/libquadshade-embree.so" ]; then  # built with the ray caster
    raycast=$(loaded "$quadshade" render "$plane" --size 16x16 --backend raycast -o "$work/raycast.png")
    require "a ray-cast render" 'libquadshade-embree' "$raycast"
    require "a ray-cast render" 'libembree' "$raycast"
fi

# quadshade with a broken image module beside it: --help and a render to PNG run, a render to
# OpenEXR names OpenImageIO.
mkdir -p "$work/copy/bin" "$work/copy/bin/$modules"
cp "$quadshade" "$work/copy/bin/quadshade"
: > "$work/copy/bin/$modules/libquadshade-openimageio.so"
"$work/copy/bin/quadshade" --help > /dev/null
"$work/copy/bin/quadshade" render "$plane" --size 16x16 -o "$work/without-module.png" 2> /dev/null
if "$work/copy/bin/quadshade" render "$plane" --size 16x16 -o "$work/none.exr" 2> "$work/broken.txt"; then
    echo "loaded_libraries.sh: a render without its image module succeeded" >&2
    exit 1
else
    status=$?
fi
cat "$work/broken.txt"
[ "$status" -eq 1 ] || { echo "loaded_libraries.sh: exit $status, expected 1" >&2; exit 1; }
grep -q 'cannot load OpenImageIO (needed to read and write images): .*libquadshade-openimageio.so' "$work/broken.txt"
[ ! -e "$work/none.exr" ] || { echo "loaded_libraries.sh: an output was left" >&2; exit 1; }
echo "each command loaded only the libraries it uses"
