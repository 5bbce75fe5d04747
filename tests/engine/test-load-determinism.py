# The tools and tests read exemplars into CIE Lab with the same numbers in
# every process (tools/image-io.c through operations/op-lab.c), whatever
# conversion paths babl would pick: babl chooses among its paths by timing
# them and caches the choice per user, and a 1e-7 difference in the
# exemplar becomes a different texture. Each child process synthesises
# with engine-time under another babl tolerance and a fresh babl cache;
# the result hashes must agree.
# Usage: test-load-determinism.py ENGINE_TIME
# SPDX-License-Identifier: LGPL-3.0-or-later
import os
import subprocess
import sys
import tempfile

engine_time = sys.argv[1]
exemplars = os.environ.get("TEXSYNTH_EXEMPLARS", "")
names = ("bark.png", "granite1.png", "brick.png")  # RGB and grey PNGs
paths = [os.path.join(exemplars, n) for n in names]
missing = [p for p in paths if not os.path.isfile(p)]
if missing:
    print("FAIL  exemplars not found: %s (TEXSYNTH_EXEMPLARS=%s)" % (missing, exemplars))
    sys.exit(1)

results = {}
for tolerance in (None, "0", "0.01"):
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, XDG_CACHE_HOME=cache, OMP_NUM_THREADS="2")
        env.pop("BABL_TOLERANCE", None)
        if tolerance is not None:
            env["BABL_TOLERANCE"] = tolerance
        run = subprocess.run([engine_time, "-s", "48"] + paths, env=env,
                             capture_output=True, text=True, timeout=300)
        if run.returncode != 0:
            print("FAIL  engine-time failed: %s" % run.stderr)
            sys.exit(1)
        hashes = tuple(line.split()[-1] for line in run.stdout.splitlines())
        label = "BABL_TOLERANCE=%s" % (tolerance if tolerance is not None else "(unset)")
        print("      %-24s %s" % (label, " ".join(hashes)))
        results[label] = hashes

ok = len(set(results.values())) == 1 and all(len(h) == len(names) for h in results.values())
print("%s  the same results under every babl tolerance, each with a fresh babl cache"
      % ("ok  " if ok else "FAIL"))
sys.exit(0 if ok else 1)
