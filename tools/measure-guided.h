/* texsynth-measure's guided measures: loading the guides, measuring each
 * result and printing the figures (guided-metrics.h defines them).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_MEASURE_GUIDED_H
#define TS_MEASURE_GUIDED_H

#include <stdbool.h>

/* paths[0] is the exemplar, paths[1..] results. With both guides, the
 * label measures; with `style_target`, the style measures. Prints the
 * figures (JSON lines with `json`) only if every result was measured;
 * returns the exit status (2 after a message on stderr). */
int ts_measure_guided_results (const char *const *paths, int n_paths, const char *exemplar_guide,
                               const char *target_guide, const char *style_target, bool json,
                               bool several);

#endif
