# texsynth:volume-load through GObject introspection on files that are not
# valid volumes: empty, truncated (header and data, by one byte), every
# header field out of range (oversized and "negative" sizes that would
# need terabytes, bad channel counts, versions, magic, DDS dimensions),
# random bytes with and without a valid magic, and valid files with random
# header bytes changed. Each must give one warning starting with the op's
# name and an empty result, never a crash, a hang or a huge allocation;
# a mutated file may also still be a valid volume, then it must render.
# The gegl tool on a few of these is in tests/volume-file/test-volume-load.py;
# the readers alone are fuzzed by fuzz/fuzz-volume-read.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import random
import resource
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "volume-ops"))
import volops  # noqa: E402
from volops import LOAD, node, tsops  # noqa: E402
from tsops import check, note  # noqa: E402

RANDOM_FILES = 24
MUTATED_FILES = 24


def vol(size=4, channels=4, version=4, bytes_per_channel=1, magic=b"VOLU", data=None):
    header = bytearray(4096)
    header[0:4] = magic
    struct.pack_into("<i", header, 4, version)
    header[8:12] = b"test"
    header[264] = 1
    struct.pack_into("<III", header, 268, size & 0xFFFFFFFF, channels & 0xFFFFFFFF,
                     bytes_per_channel & 0xFFFFFFFF)
    if data is None:
        data = bytes(i % 251 for i in range(size ** 3 * channels)) if size <= 64 else b""
    return bytes(header) + data


def dds(width=4, height=4, depth=4, header_size=124, dx10=True, dxgi=28, dimension=4,
        data=None):
    h = bytearray(128)
    h[0:4] = b"DDS "
    struct.pack_into("<7I", h, 4, header_size, 0x80100F, height & 0xFFFFFFFF,
                     width & 0xFFFFFFFF, (width * 4) & 0xFFFFFFFF, depth & 0xFFFFFFFF, 1)
    struct.pack_into("<2I", h, 76, 32, 0x4)
    h[84:88] = b"DX10" if dx10 else b"DXT1"
    struct.pack_into("<2I", h, 108, 0x1008, 0x200000)
    if dx10:
        h += struct.pack("<5I", dxgi, dimension, 0, 1, 0)
    if data is None:
        n = width * height * depth * 4
        data = bytes(i % 253 for i in range(n)) if 0 < n <= 1 << 20 else b""
    return bytes(h) + data


def bad_inputs():
    """(label, file name, bytes, words one of which the warning holds)."""
    good_vol, good_dds = vol(), dds()
    truncated = ("truncated",)
    large = ("too large", "exceeds", "do not fit")
    malformed = ("malformed", "is not", "only", "truncated", "not supported", "refused",
                 "cannot", "DXGI", "depth", "cube", "volume")
    return [
        ("empty .vol", "empty.vol", b"", truncated + ("is not a volume",)),
        ("empty .dds", "empty.dds", b"", truncated + ("is not a volume",)),
        (".vol header cut at 100 bytes", "cut.vol", good_vol[:100], truncated),
        (".vol header only", "header.vol", good_vol[:4096], truncated),
        (".vol one byte short", "short.vol", good_vol[:-1], truncated),
        (".vol size 0", "size0.vol", vol(size=0, data=b""), large + malformed),
        (".vol size -1 (0xFFFFFFFF)", "minus1.vol", vol(size=-1), large),
        (".vol size 2^31-1", "int-max.vol", vol(size=0x7FFFFFFF), large),
        (".vol size 4097 (over the format's 4096)", "4097.vol", vol(size=4097), large),
        (".vol size 4000 (256 GB of voxels)", "4000.vol", vol(size=4000), large),
        (".vol size 1000 (4 GB, over the 2 GiB cap)", "1000.vol", vol(size=1000), large),
        (".vol 0 channels", "ch0.vol", vol(channels=0), ("channels",)),
        (".vol 5 channels", "ch5.vol", vol(channels=5), ("channels",)),
        (".vol -1 channels", "chm1.vol", vol(channels=-1), ("channels",)),
        (".vol 2 bytes per channel", "bpc2.vol", vol(bytes_per_channel=2), ("bytes per channel",)),
        (".vol 0 bytes per channel", "bpc0.vol", vol(bytes_per_channel=0), ("bytes per channel",)),
        (".vol version 3", "v3.vol", vol(version=3), ("version",)),
        (".vol wrong magic", "magic.vol", vol(magic=b"VOLX"), ("is not a volume",)),
        (".dds magic only", "magic.dds", b"DDS ", truncated),
        (".dds header cut at 100 bytes", "cut.dds", good_dds[:100], truncated),
        (".dds DX10 header cut", "cut10.dds", good_dds[:130], truncated),
        (".dds one byte short", "short.dds", good_dds[:-1], truncated),
        (".dds header size 100", "hsize.dds", dds(header_size=100), malformed),
        (".dds width 0", "w0.dds", dds(width=0), malformed),
        (".dds depth 0", "d0.dds", dds(depth=0), malformed),
        (".dds 2^32-1 cubed", "huge.dds", dds(width=-1, height=-1, depth=-1), large + malformed),
        (".dds 65536 cubed", "65536.dds", dds(width=65536, height=65536, depth=65536),
         large + malformed),
        (".dds 2048 cubed (32 GB)", "2048.dds", dds(width=2048, height=2048, depth=2048),
         large + malformed),
        (".dds not a cube", "box.dds", dds(width=4, height=8, depth=4), malformed),
        (".dds BC1", "bc1.dds", dds(dxgi=71), ("DXGI format 71",)),
        (".dds 2D texture", "2d.dds", dds(dimension=3), malformed),
        (".dds legacy DXT1", "dxt1.dds", dds(dx10=False), malformed),
    ]


def load(path):
    """(warnings, (width, height) or None): None is an empty result."""
    Gegl = tsops.gegl()
    text = [""]
    with volops.captured_stderr(text):
        graph = Gegl.Node()
        n = node(graph, LOAD, path=path, index=0)
        box = n.get_bounding_box()
        size = None
        if box.width > 0 and box.height > 0:
            w, h, px = volops.render_u8(n)
            size = (w, h)
    return volops.op_warnings(text[0], LOAD), size


def main():
    volops.require_ops(LOAD)
    work = tsops.workdir()
    # A reader that trusted a header would try to allocate terabytes: cap
    # this process's memory, so that shows as a failure, not as swapping.
    # (Not under ASan, whose shadow memory is terabytes of address space;
    # there ASan itself reports a huge allocation.)
    if "asan" not in os.environ.get("LD_PRELOAD", ""):
        resource.setrlimit(resource.RLIMIT_AS, (6 << 30, 6 << 30))

    note("-- crafted bad files")
    outcomes = {}
    for label, name, data, words in bad_inputs():
        path = os.path.join(work, name)
        with open(path, "wb") as f:
            f.write(data)
        warnings, size = load(path)
        ok = len(warnings) == 1 and any(w in warnings[0] for w in words) and size is None
        outcomes[ok] = outcomes.get(ok, 0) + 1
        check(ok, "%s: %s, %s" % (label, warnings[0] if warnings else "no warning",
                                  "empty result" if size is None else "a %dx%d result" % size))

    note("-- random files (seeded)")
    rng = random.Random(8)
    quiet = 0
    for i in range(RANDOM_FILES):
        prefix = (b"", b"VOLU", b"DDS ")[i % 3]
        data = prefix + bytes(rng.getrandbits(8) for _ in range(rng.choice((0, 7, 200, 4200))))
        path = os.path.join(work, "random-%02d.%s" % (i, "dds" if i % 3 == 2 else "vol"))
        with open(path, "wb") as f:
            f.write(data)
        warnings, size = load(path)
        quiet += not (len(warnings) == 1 and size is None)
    check(quiet == 0, "%d random files (a third with a .vol or DDS magic): one warning and an "
          "empty result each (%d not)" % (RANDOM_FILES, quiet))

    note("-- valid files with random header bytes changed (seeded)")
    valid = bad = 0
    for i in range(MUTATED_FILES):
        data = bytearray(vol() if i % 2 == 0 else dds())
        header = 280 if i % 2 == 0 else 148
        for _ in range(rng.randint(1, 4)):
            data[rng.randrange(header)] = rng.getrandbits(8)
        path = os.path.join(work, "mutated-%02d.%s" % (i, "vol" if i % 2 == 0 else "dds"))
        with open(path, "wb") as f:
            f.write(data)
        warnings, size = load(path)
        if size is not None and not warnings:
            valid += 1
        elif size is None and len(warnings) == 1:
            bad += 1
    check(valid + bad == MUTATED_FILES,
          "%d mutated files: %d still valid and rendered, %d refused with one warning, "
          "%d otherwise" % (MUTATED_FILES, valid, bad, MUTATED_FILES - valid - bad))
    note("bad inputs: %d crafted (%d as expected), %d random, %d mutated; no crash"
         % (sum(outcomes.values()), outcomes.get(True, 0), RANDOM_FILES, MUTATED_FILES))
    tsops.finish()


if __name__ == "__main__":
    main()
