/* Texture by numbers in layers (internal): each label of the target is
 * filled by a plain synthesis of that label's texture alone, and only
 * the bands along the target's label edges are synthesised again under
 * the guide.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_GUIDE_LAYERS_H
#define TS_GUIDE_LAYERS_H

#include "texsynth.h"

/* The route (taken where ts_guide_layers_apply says, guide-params.h),
 * for validated params and an output of their size;
 * same contract as ts_synthesize. */
TsStatus ts_guide_layers_synthesize (const TsParams *params, const TsImage *exemplar,
                                     TsImage *output, TsProgressFunc progress, void *user_data,
                                     TsError *error);

#endif
