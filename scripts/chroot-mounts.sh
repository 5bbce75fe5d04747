# shellcheck shell=bash
# Mounts into chroots, all undone on exit, shared by scripts/gimp3-env and
# scripts/debian-check (sourced, not run).
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# The caller sets chroot_caller (its name, for messages) before sourcing.
# Sourcing installs the EXIT trap that undoes every mount made here.

: "${chroot_caller:?set chroot_caller before sourcing chroot-mounts.sh}"
chroot_mounted=()

# Undo this script's mounts, last first.
chroot_unmount_all() {
  local i
  for ((i = ${#chroot_mounted[@]} - 1; i >= 0; i--)); do
    umount "${chroot_mounted[i]}" 2>/dev/null || umount -l "${chroot_mounted[i]}" 2>/dev/null ||
      echo "$chroot_caller: could not unmount ${chroot_mounted[i]}" >&2
  done
  chroot_mounted=()
}
trap chroot_unmount_all EXIT
trap 'exit 130' INT TERM

# Mount only what is not mounted yet: a run in parallel may share it, and
# then it is that run's to undo.
chroot_mount() { # chroot_mount TARGET MOUNT-ARGS...
  local target="$1"; shift
  mkdir -p "$target"
  if ! mountpoint -q "$target"; then
    mount "$@" "$target"
    chroot_mounted+=("$target")
  fi
}

# What programs in a chroot expect of /proc and /dev.
chroot_mount_system() { # chroot_mount_system ROOT
  chroot_mount "$1/proc" -t proc proc
  chroot_mount "$1/dev" --bind /dev
  chroot_mount "$1/dev/pts" --bind /dev/pts
  chroot_mount "$1/dev/shm" -t tmpfs -o mode=1777 tmpfs
}

# Exits if anything is mounted at or below a DIR: deleting the folder
# would delete what a bind mount shows there (/dev, the source tree).
chroot_assert_unmounted() { # chroot_assert_unmounted DIR...
  local dir
  for dir in "$@"; do
    if awk '{print $2}' /proc/mounts | grep -qE "^$dir(/|$)"; then
      echo "$chroot_caller: something is still mounted below $dir; not deleting it" >&2
      exit 1
    fi
  done
}
