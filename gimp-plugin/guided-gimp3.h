/* GIMP 3's guided procedures (guided-gimp3.c).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_GUIDED_GIMP3_H
#define TEXSYNTH_GUIDED_GIMP3_H

#include <libgimp/gimp.h>

/* `names` with plug-in-texsynth-texture-by-numbers and -style-transfer
 * appended. */
GList         *ts_guided_names3     (GList *names);
/* The procedure called `name` if it is one of those two, else NULL. */
GimpProcedure *ts_guided_procedure3 (GimpPlugIn *plug_in, const gchar *name);

#endif /* TEXSYNTH_GUIDED_GIMP3_H */
