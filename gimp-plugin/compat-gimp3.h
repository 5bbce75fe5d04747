/* GIMP 3 glue shared by its files (compat-gimp3.c, heal-gimp3.c).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_COMPAT_GIMP3_H
#define TEXSYNTH_COMPAT_GIMP3_H

#include <libgimp/gimp.h>

#include "texsynth-plugin.h"

/* The return values of a failed run, with `message` (taken; may be NULL). */
GimpValueArray *failure (GimpProcedure *procedure, GimpPDBStatusType status, gchar *message);

/* Checks common to all procedures: one to `max` layers, the ops found;
 * NULL if fine, else a message. */
gchar *check_drawables (GimpDrawable **drawables, gint max);

/* plug-in-texsynth-heal-selection, -heal-transparency and -uncrop. */
GimpValueArray *ts_run_heal3 (GimpProcedure *procedure, GimpRunMode mode, GimpImage *image,
                              GimpDrawable **drawables, GimpProcedureConfig *config,
                              gpointer data);

#endif /* TEXSYNTH_COMPAT_GIMP3_H */
