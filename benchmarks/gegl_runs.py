# What the 2D benchmark scripts run through the gegl tool: the
# environment that finds the build's operations, a central crop, and one
# texsynth:synthesize result per seed.
# SPDX-License-Identifier: LGPL-3.0-or-later
import os
import subprocess


def quiet_runs(build):
    """Keyword arguments for subprocess.run: the build's operations
    before GEGL's own, output dropped, failure raised."""
    plugins = subprocess.check_output(["pkg-config", "--variable=pluginsdir", "gegl-0.4"],
                                      text=True).strip()
    env = dict(os.environ, GEGL_PATH=os.path.join(build, "operations") + ":" + plugins)
    return dict(env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)


def crop_centre(source, width, height, out, quiet, side=128):
    """Writes the central crop of at most side x side of a width x height
    image to out; returns its width and height."""
    crop_w, crop_h = min(width, side), min(height, side)
    subprocess.run(["gegl", "-i", source, "-o", out, "--", "gegl:crop",
                    "x=%d" % ((width - crop_w) // 2), "y=%d" % ((height - crop_h) // 2),
                    "width=%d" % crop_w, "height=%d" % crop_h], **quiet)
    return crop_w, crop_h


def synthesize_seeds(exemplar, out_dir, name, size, seeds, quiet):
    """Grows exemplar to size x size once per seed (a comma-separated
    list); returns the results' paths, out_dir/name-SEED.png."""
    results = []
    for seed in seeds.split(","):
        result = os.path.join(out_dir, "%s-%s.png" % (name, seed))
        subprocess.run(["gegl", "-i", exemplar, "-o", result, "--", "texsynth:synthesize",
                        "width=%d" % size, "height=%d" % size, "seed=" + seed], **quiet)
        results.append(result)
    return results
