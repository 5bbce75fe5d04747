/* GIMP 3's heal procedures (heal-gimp3.c).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_HEAL_GIMP3_H
#define TEXSYNTH_HEAL_GIMP3_H

#include <libgimp/gimp.h>

/* plug-in-texsynth-heal-selection, -heal-transparency and -uncrop. */
GimpValueArray *ts_run_heal3 (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image,
                              GimpDrawable **drawables, GimpProcedureConfig *config,
                              gpointer data);

#endif /* TEXSYNTH_HEAL_GIMP3_H */
