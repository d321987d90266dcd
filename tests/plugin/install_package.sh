#!/bin/sh
# install_package.sh BUILD_DIR PREFIX: the installed package in a clean prefix, as a user gets it
# (the plugin tests' fixture).
set -eu
build=$1 prefix=$2
rm -rf "$prefix"
mkdir -p "$prefix"
cmake --install "$build" --prefix "$prefix" > "$prefix.install.log"
test -x "$prefix/bin/quadshade"
