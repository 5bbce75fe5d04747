/* Style transfer's tone step (internal): the result's lightness, at the
 * scale of the picture's layout, moved towards the picture's.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_STYLE_TONE_H
#define TS_STYLE_TONE_H

#include "texsynth.h"

#include <stdbool.h>

/* Moves `output`'s tone (CIE L blurred by TS_STYLE_GUIDE_BLUR)
 * weight / (1 + weight) of the way (the guide's share against the
 * texture's coherence) to the picture's: `guides`' target guide, blurred
 * alike and moved to the exemplar's mean and spread of tone. The
 * difference is added to the L of the visible pixels; finer detail is
 * left as synthesised. The blur wraps across a tileable side (`wrap_x`,
 * `wrap_y`), so the result still tiles. */
TsStatus ts_style_tone (const TsGuides *guides, const TsImage *exemplar, bool wrap_x,
                        bool wrap_y, TsImage *output);

#endif
