#!/usr/bin/env bash
# Installs the Debian 12 packages texsynth needs to build, run and test.
# SPDX-License-Identifier: LGPL-3.0-or-later
set -euo pipefail

packages=(
  gcc libc6-dev pkg-config meson ninja-build   # toolchain (OpenMP: gcc's libgomp)
  libgegl-dev libbabl-dev libglib2.0-dev        # engine tools and GEGL operations
  gegl                                          # the gegl command-line tool
  python3 python3-gi gir1.2-gegl-0.4            # op tests from Python (GObject introspection)
  gettext locales                               # translations (po/) and their tests' locales
  gimp libgimp2.0-dev                           # the GIMP 2.10 plug-in and its tests (gimp-console-2.10)
  debootstrap                                   # scripts/gimp3-env: the GIMP 3 chroot (Debian 13)
  xvfb xauth imagemagick                        # headless X and screen grabs for dialog screenshots
  clang libclang-rt-14-dev libomp-14-dev valgrind  # scripts/sanitize.sh, fuzz/run.sh: libFuzzer,
                                                #   TSan with LLVM libomp + Archer, memcheck
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo=()
[ "$(id -u)" -eq 0 ] || sudo=(sudo)
if [ ${#missing[@]} -gt 0 ]; then
  apt=("${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get)
  "${apt[@]}" update
  "${apt[@]}" install -y --no-install-recommends "${missing[@]}"
fi

# tests/i18n shows the ops in these languages; a clean Debian has no locales.
for lang in et_EE es_ES fi_FI hr_HR zh_CN; do
  locale -a 2>/dev/null | grep -qix "$lang\.utf-\?8" ||
    "${sudo[@]}" localedef -i "$lang" -f UTF-8 "$lang.UTF-8"
done
