# Stands in for a test that cannot run on this machine: prints why (the
# arguments) and exits 77, which meson reports as SKIP with that reason in
# the log, so a missing tool is seen rather than the test left out.
# SPDX-License-Identifier: LGPL-3.0-or-later

import sys

print("SKIP  " + " ".join(sys.argv[1:]), flush=True)
sys.exit(77)
