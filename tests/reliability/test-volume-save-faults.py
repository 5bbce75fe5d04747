# texsynth:volume-save under file-system faults: a full disk (a 128 KiB
# tmpfs in a private mount namespace), a file size limit (RLIMIT_FSIZE in
# the gegl tool's process), a read-only file system, an unwritable folder,
# and the process killed midway. Every case must give a warning that names
# the problem, leave the older files at the paths byte for byte as they
# were, and leave no new or temporary file behind.
#
# The mount namespace is root's own, or for any other user one inside a
# user namespace where the user is root (unshare -r). Where none can be
# made, the full disk is a file size limit below every file's size, and
# the unwritable folder stands for the read-only file system. Root writes
# through permissions, so for the unwritable folder the gegl process runs
# in a user namespace (unshare --user); where root can make neither kind
# of namespace, the test exits 77 saying what it could not check, once
# every check it could make has passed.
#
# GEGL 0.4 has no way to cancel an operation once its process() runs
# (gegl_operation_progress() returns nothing, and hosts such as GIMP stop
# a GeglProcessor only between chunks), so a cancel of the save itself
# cannot happen; the engine-level cancel of ts_synthesize_solid is tested
# by test-cancel, and here the process is killed during the synthesis.
# A missing folder and other bad paths are in tests/volume-ops/test-volume-save.py.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import resource
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "ops"))
import tsops  # noqa: E402
from tsops import check, note  # noqa: E402

SAVE = "texsynth:volume-save"
SETTINGS = ["seed=7", "iterations=2"]
TMPFS_KIB = 128
FILE_LIMIT = 16384          # bytes: a 16^3 .vol (16 KiB) or more is refused
NAMESPACE_FLAG = "--in-mount-namespace"


def child_env(scratch):
    """babl and GEGL keep caches under XDG_CACHE_HOME: a fault must not
    touch the user's (a truncated babl fish cache would outlive the test)."""
    env = dict(os.environ)
    env["XDG_CACHE_HOME"] = os.path.join(scratch, "cache")
    env["HOME"] = scratch
    return env


def gegl_save(scratch, path, size, preexec=None, wait=True, extra=(), prefix=()):
    """gegl -i bark.png -- texsynth:volume-save path=... size=... (run
    under the command `prefix`, if any): the process, or (returncode,
    warnings)."""
    args = list(prefix) + [tsops.gegl_binary(), "-i", tsops.exemplar("bark.png"), "--", SAVE,
                           "path=" + path, "size=%d" % size] + SETTINGS + list(extra)
    proc = subprocess.Popen(args, env=child_env(scratch), stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=preexec, restore_signals=preexec is None)
    if not wait:
        return proc
    try:
        _, err = proc.communicate(timeout=600)
    except subprocess.TimeoutExpired:
        proc.kill()
        tsops.die("%s did not finish within 600 s" % " ".join(args))
    if proc.returncode < 0:
        check(False, "gegl was killed by signal %d: %s" % (-proc.returncode, err[-2000:]))
    return proc.returncode, [line.split(SAVE + ": ", 1)[1] for line in err.splitlines()
                             if SAVE + ": " in line]


def snapshot(folder):
    """Every file under `folder` with its bytes."""
    files = {}
    for root, _, names in os.walk(folder):
        for name in names:
            path = os.path.join(root, name)
            with open(path, "rb") as f:
                files[os.path.relpath(path, folder)] = f.read()
    return files


def plant_older_files(folder, slices=4):
    """Older files at every path the saves below use (small, so they
    leave most of a full-disk tmpfs free)."""
    os.makedirs(os.path.join(folder, "slices"), exist_ok=True)
    for name in ("old.vol", "old.dds", "old.png"):
        with open(os.path.join(folder, name), "wb") as f:
            f.write(b"older " + name.encode() + b" that must survive\n")
    for i in range(slices):
        with open(os.path.join(folder, "slices", "slice-%03d.png" % i), "wb") as f:
            f.write(b"older slice %d\n" % i)


def expect_refusal(label, warnings, words, folder, before):
    after = snapshot(folder)
    check(warnings and any(w in warnings[0] for w in words),
          "%s: warns %s (got %s)" % (label, " or ".join(repr(w) for w in words),
                                     warnings[0] if warnings else "no warning"))
    check(after == before, "%s: older files intact, nothing new or temporary (%s)"
          % (label, sorted(set(after) ^ set(before)) or "same files, same bytes"))


# --- a file size limit --------------------------------------------------------

def limit_file_size(limit=FILE_LIMIT):
    """A preexec_fn: files of the process may grow to `limit` bytes."""
    def preexec():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
        # Ignored, the signal becomes EFBIG from write(), as a quota would.
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    return preexec


def file_size_limit(scratch):
    note("-- RLIMIT_FSIZE of %d bytes in the gegl process" % FILE_LIMIT)
    folder = os.path.join(scratch, "limited")
    plant_older_files(folder)
    before = snapshot(folder)
    # 32^3: the .vol, .dds and atlas are each over the limit (PNG slices
    # of 3 KB each are not: the full disk below fails them).
    for name in ("old.vol", "old.dds", "old.png"):
        code, warnings = gegl_save(scratch, os.path.join(folder, name), 32,
                                   preexec=limit_file_size())
        expect_refusal("file size limit, %s" % name, warnings,
                       ("File too large", "did not write the whole image"), folder, before)


# --- killed midway ------------------------------------------------------------

def killed_midway(scratch):
    note("-- the gegl process killed during the synthesis")
    folder = os.path.join(scratch, "killed")
    plant_older_files(folder)
    before = snapshot(folder)
    proc = gegl_save(scratch, os.path.join(folder, "old.vol"), 96, wait=False)
    time.sleep(1.5)
    running = proc.poll() is None
    proc.kill()
    proc.communicate()
    check(running, "the synthesis of a 96^3 volume was still running after 1.5 s")
    check(snapshot(folder) == before, "killed: older files intact, nothing new")


# --- unwritable folders -------------------------------------------------------

# Root writes whatever the permissions say, but not from a user namespace
# of its own: there it has no power over the host's files, whose owner
# (root) it stays, so their permission bits hold.
USER_NAMESPACE = ["unshare", "--user"]


def without_root_powers():
    """The command prefix that makes the folder's permissions hold for
    the gegl process, or None (root without user namespaces)."""
    if os.geteuid() != 0:
        return []
    if shutil.which("unshare") and subprocess.run(USER_NAMESPACE + ["true"],
                                                  capture_output=True).returncode == 0:
        return USER_NAMESPACE
    return None


def unwritable_folder(scratch, prefix):
    note("-- a folder without write permission%s" % (" (gegl in a user namespace)"
                                                      if prefix else ""))
    folder = os.path.join(scratch, "unwritable")
    plant_older_files(folder)
    before = snapshot(folder)
    for sub in (folder, os.path.join(folder, "slices")):
        os.chmod(sub, 0o555)
    try:
        for name in ("old.vol", "slices/"):
            code, warnings = gegl_save(scratch, os.path.join(folder, name), 8, prefix=prefix)
            expect_refusal("unwritable folder, %s" % name, warnings, ("Permission denied",),
                           folder, before)
    finally:
        for sub in (folder, os.path.join(folder, "slices")):
            os.chmod(sub, 0o755)


# --- a full disk, then a read-only one (tmpfs in a private mount namespace) ---

def full_and_read_only_disk(scratch):
    folder = os.path.join(scratch, "tmpfs")
    os.mkdir(folder)
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=%dk,mode=0755" % TMPFS_KIB,
                       "texsynth-test", folder]).returncode != 0:
        check(False, "mount a tmpfs in the private mount namespace")
        return
    try:
        note("-- a full disk: %d KiB tmpfs" % TMPFS_KIB)
        plant_older_files(folder)
        free = shutil.disk_usage(folder).free
        before = snapshot(folder)
        # 40^3: a .vol of 196 KB, a .dds of 256 KB, an atlas of about as
        # much, 40 PNG slices of about 4 KB each: all more than is free, the
        # slices only after some of them have been written.
        for name, extra in (("old.vol", ()), ("old.dds", ()), ("old.png", ()),
                            ("slices/", ()), ("slices", ("format=png-slices",))):
            code, warnings = gegl_save(scratch, os.path.join(folder, name), 40, extra=extra)
            expect_refusal("full disk, %s%s" % (name, " " + extra[0] if extra else ""),
                           warnings, ("No space left on device", "did not write the whole image"),
                           folder, before)
            check(shutil.disk_usage(folder).free == free,
                  "full disk, %s: all the space is free again (%d bytes)" % (name, free))

        note("-- a read-only file system")
        # A read-only bind of the mount, which a user namespace may make
        # where it may not remount the tmpfs itself read-only.
        subprocess.run(["mount", "-o", "remount,bind,ro", folder], check=True)
        for name in ("old.vol", "slices/"):
            code, warnings = gegl_save(scratch, os.path.join(folder, name), 8)
            expect_refusal("read-only file system, %s" % name, warnings,
                           ("Read-only file system",), folder, before)
    finally:
        subprocess.run(["umount", folder])


def mount_namespace():
    """The unshare command for a private mount namespace (in a user
    namespace of its own when not root), or (None, why not)."""
    if not shutil.which("unshare"):
        return None, "unshare is not installed (Debian package util-linux)"
    command = ["unshare", "--mount", "--propagation", "private"]
    if os.geteuid() != 0:
        command[1:1] = ["--user", "--map-root-user"]
    probe = subprocess.run(command + ["true"], capture_output=True, text=True)
    if probe.returncode != 0:
        return None, "%s failed: %s" % (" ".join(command), probe.stderr.strip())
    return command, None


def in_namespace(command):
    """This script again in a private mount namespace, so its tmpfs
    vanishes with it whatever happens."""
    proc = subprocess.run(command + [sys.executable, os.path.abspath(__file__), NAMESPACE_FLAG],
                          capture_output=True, text=True, timeout=900)
    sys.stdout.write(proc.stdout)
    check(proc.returncode == 0, "the full-disk and read-only checks pass%s"
          % ("" if proc.returncode == 0 else ":\n" + proc.stderr[-3000:]))


def full_disk_as_file_limit(scratch):
    """Without a tmpfs: every file the saves write meets a file size
    limit below its size, as a full disk would (EFBIG, not ENOSPC)."""
    note("-- a full disk as a file size limit of 1 KiB (no mount namespace)")
    folder = os.path.join(scratch, "full")
    plant_older_files(folder)
    before = snapshot(folder)
    for name, extra in (("old.vol", ()), ("old.png", ()), ("slices/", ()),
                        ("slices", ("format=png-slices",))):
        code, warnings = gegl_save(scratch, os.path.join(folder, name), 40, extra=extra,
                                   preexec=limit_file_size(1024))
        expect_refusal("full disk as a file size limit, %s%s"
                       % (name, " " + extra[0] if extra else ""), warnings,
                       ("File too large", "did not write the whole image"), folder, before)


def main():
    code, _, _ = tsops.run_gegl(["--exists", SAVE])
    if code != 0:
        tsops.die("gegl cannot find %s (GEGL_PATH=%s)" % (SAVE, os.environ.get("GEGL_PATH")))
    scratch = tsops.workdir()
    if NAMESPACE_FLAG in sys.argv:
        full_and_read_only_disk(scratch)
        tsops.finish()
    file_size_limit(scratch)
    killed_midway(scratch)
    not_made = []
    prefix = without_root_powers()
    if prefix is not None:
        unwritable_folder(scratch, prefix)
    else:
        not_made.append("the unwritable folder: root writes through its permissions and "
                        "cannot make a user namespace here")
    command, why = mount_namespace()
    if command:
        in_namespace(command)
    else:
        note("no mount namespace (%s)%s" % (why, "" if prefix is None else
                                             ": the unwritable folder stands for a read-only "
                                             "file system"))
        full_disk_as_file_limit(scratch)
        if prefix is None:
            not_made.append("the read-only file system: no mount namespace (%s)" % why)
    tsops.finish(skipped="; ".join(not_made))


if __name__ == "__main__":
    main()
