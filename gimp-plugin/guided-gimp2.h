/* GIMP 2.10's guided procedures (guided-gimp2.c).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_GUIDED_GIMP2_H
#define TEXSYNTH_GUIDED_GIMP2_H

#include "compat-gimp2.h"

/* Installs plug-in-texsynth-texture-by-numbers and -style-transfer. */
void     ts_install_guided2 (void);
/* Runs either of them; FALSE for another name. */
gboolean ts_run_guided2     (const gchar *name, GimpRunMode mode, const GimpParam *params,
                             gint n_params, Outcome *outcome);

#endif /* TEXSYNTH_GUIDED_GIMP2_H */
