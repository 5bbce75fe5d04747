#!/usr/bin/env bash
# Installs the Debian 12 packages texsynth needs to build, run and test.
# SPDX-License-Identifier: LGPL-3.0-or-later
set -euo pipefail

packages=(
  gcc libc6-dev pkg-config meson ninja-build   # toolchain (OpenMP: gcc's libgomp)
  libgegl-dev libbabl-dev libglib2.0-dev        # engine tools and GEGL operations
  gegl                                          # the gegl command-line tool
  python3 python3-gi gir1.2-gegl-0.4            # op tests from Python (GObject introspection)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

apt=(env DEBIAN_FRONTEND=noninteractive apt-get)
[ "$(id -u)" -eq 0 ] || apt=(sudo "${apt[@]}")
"${apt[@]}" update
"${apt[@]}" install -y --no-install-recommends "${missing[@]}"
