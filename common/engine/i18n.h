/* Translation of the engine's messages, without GLib: glibc's dgettext in
 * the "texsynth" domain. The program that shows the messages (the GEGL
 * ops, the GIMP plug-in) binds the domain to its locale folder.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TEXSYNTH_I18N_H
#define TEXSYNTH_I18N_H

#define TS_TEXT_DOMAIN "texsynth"

#ifdef ENABLE_NLS
#include <libintl.h>
#define TS_(s) dgettext (TS_TEXT_DOMAIN, s)
#else
#define TS_(s) ((const char *) (s))
#endif

/* Marks a string for extraction only; it is translated where shown, with
 * TS_() (the format strings of ts_fail() are translated by ts_fail()). */
#define TS_N_(s) (s)

#endif
