# Shared by the autopkgtests: a scratch folder, an environment with no
# GEGL_PATH and a fresh HOME (so only the installed packages can be
# found), and PNG helpers that need nothing but coreutils.
# SPDX-License-Identifier: LGPL-3.0-or-later

work="${AUTOPKGTEST_TMP:?AUTOPKGTEST_TMP is not set (autopkgtest sets it)}"
unset GEGL_PATH GIMP2_DIRECTORY GIMP3_DIRECTORY XDG_CONFIG_HOME XDG_DATA_HOME XDG_CACHE_HOME DISPLAY
HOME="$work/home"
export HOME
mkdir -p "$HOME"

# The exemplar: a GIMP pattern bundled in the source tree (cwd).
exemplar="$PWD/examples/brick.png"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

pass() {
  echo "ok: $*"
}

# "WIDTHxHEIGHT BITS COLOUR-TYPE" from a PNG's header, or a failure.
png_header() {
  [ -s "$1" ] || fail "$1 was not written"
  [ "$(od -An -tx1 -N8 "$1" | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "$1 is not a PNG"
  # shellcheck disable=SC2046 # the 10 header bytes, one word each
  set -- $(od -An -tu1 -j16 -N10 "$1")
  echo "$(( ($1 << 24) | ($2 << 16) | ($3 << 8) | $4 ))x$(( ($5 << 24) | ($6 << 16) | ($7 << 8) | $8 )) $9 ${10}"
}

png_size() {
  png_header "$1" | cut -d' ' -f1
}
