/* GIMP 2.10's heal procedures (heal-gimp2.c).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_HEAL_GIMP2_H
#define TEXSYNTH_HEAL_GIMP2_H

#include "compat-gimp2.h"

/* plug-in-texsynth-heal-selection, -heal-transparency and -uncrop. */
gboolean ts_run_heal2 (const gchar *name, GimpRunMode mode, const GimpParam *params,
                       gint n_params, Outcome *outcome);

#endif /* TEXSYNTH_HEAL_GIMP2_H */
