# Shared by the SDK tests (sourced): installing a build tree into a scratch prefix, building an example
# of sdk/examples/ against that install out of tree, and reading 8-bit images as numbers.

step() { printf '\n=== %s\n' "$*"; }
fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }

# Installs BUILD_DIR into $prefix and checks that the installed strata links the installed libstrata_core:
# its RPATH is relative to itself, so it must not reach back into the build tree.
install_strata() {
  step "install $1 into $prefix"
  cmake --install "$1" --prefix "$prefix"
  step "the installed strata links the installed libstrata_core"
  local core
  core=$(ldd "$strata" | awk '/libstrata_core/ { print $3 }')
  echo "libstrata_core: $core"
  [[ -n $core && $(realpath "$core") == "$(realpath "$prefix/lib")"/* ]] ||
    fail "$strata links '$core', not the libstrata_core in $prefix/lib"
}

# Builds EXAMPLE_DIR against the installed package into $work/NAME, where it must make ARTEFACT (a plugin
# strata-NAME.so, or an application), with the warnings Strata builds its own code with
# (cmake/StrataWarnings.cmake) as errors; GCC's -Wmissing-field-initializers would flag every designated
# initializer that leaves a member to its default.
build_example() {
  local example=$1 name=$2 artefact=$3
  step "build the $name example against the installed package, warnings as errors"
  cmake -S "$example" -B "$work/$name" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-missing-field-initializers -Werror"
  cmake --build "$work/$name" -j2
  [[ -f $work/$name/$artefact ]] || fail "the build made no $artefact"
}

# Sets up the test of sdk/examples/NAME: a scratch directory $work, removed at exit (kept, to look into,
# when KEEP_WORK is set); BUILD_DIR installed into $prefix, whose command is $strata; the example
# ($example) built against it, making ARTEFACT (by default the plugin strata-NAME.so, whose directory is
# put on STRATA_PLUGIN_PATH).
#   set_up_example BUILD_DIR SOURCE_DIR NAME [ARTEFACT]
set_up_example() {
  local build=$1 name=$3 artefact=${4:-strata-$3.so}
  example=$2/sdk/examples/$name
  work=$(mktemp -d "${TMPDIR:-/tmp}/strata-sdk-test.XXXXXX")
  trap '[[ -n ${KEEP_WORK:-} ]] || rm -rf "$work"' EXIT
  prefix=$work/prefix
  strata=$prefix/bin/strata
  install_strata "$build"
  build_example "$example" "$name" "$artefact"
  [[ $artefact != *.so ]] || export STRATA_PLUGIN_PATH=$work/$name
}

# One line "r g b" per pixel of an 8-bit image, row by row. (python3 here has no GDAL bindings; GDAL's XYZ
# driver prints one band at a time as "x y value".)
pixels() {
  paste -d ' ' <(gdal_translate -q -of XYZ -b 1 "$1" /vsistdout/ | cut -d ' ' -f 3) \
               <(gdal_translate -q -of XYZ -b 2 "$1" /vsistdout/ | cut -d ' ' -f 3) \
               <(gdal_translate -q -of XYZ -b 3 "$1" /vsistdout/ | cut -d ' ' -f 3)
}

# How many pixels of an image are within TOLERANCE levels of R G B in every channel.
count_near() {
  local image=$1 r=$2 g=$3 b=$4 tolerance=$5
  pixels "$image" | awk -v r="$r" -v g="$g" -v b="$b" -v t="$tolerance" '
    function near(value, wanted) { return value >= wanted - t && value <= wanted + t }
    near($1, r) && near($2, g) && near($3, b) { n++ }
    END { print n + 0 }'
}
