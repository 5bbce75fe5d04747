#!/usr/bin/env bash
# From a fresh Debian 12 machine to a synthesised texture: installs the
# packages, builds texsynth into build/, and grows examples/bark.png
# (82x90) into bark-1024x768.png with the texsynth:synthesize GEGL op.
# SPDX-License-Identifier: LGPL-3.0-or-later
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
[ -f build/build.ninja ] || meson setup build
ninja -C build

# GEGL_PATH replaces GEGL's own op folders, so list both.
export GEGL_PATH="$PWD/build/operations:$(pkg-config --variable=pluginsdir gegl-0.4)"
gegl --exists texsynth:synthesize >/dev/null
gegl -i examples/bark.png -o bark-1024x768.png -- \
  texsynth:synthesize width=1024 height=768 seed=3
echo "wrote $PWD/bark-1024x768.png"
