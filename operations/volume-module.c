/* The module holding texsynth:volume-slice and texsynth:volume-save.
 * SPDX-License-Identifier: LGPL-3.0-or-later
 *
 * Both ops live in one module so that they share one volume cache
 * (volume-cache.c): each op file is built with GEGL_OP_BUNDLE, and this
 * file registers their types, as GEGL's own multi-op modules do. The
 * module is linked with -z nodelete: GEGL closes a module whenever no
 * class of it is in use, and the cache must outlive that.
 */
#include <gegl-plugin.h>

#include "op-common.h" /* ts_op_bind_textdomain */

void gegl_op_texsynth_volume_slice_register_type (GTypeModule *module);
void gegl_op_texsynth_volume_save_register_type (GTypeModule *module);

G_MODULE_EXPORT const GeglModuleInfo *gegl_module_query (GTypeModule *module);
G_MODULE_EXPORT gboolean gegl_module_register (GTypeModule *module);

static const GeglModuleInfo module_info = { GEGL_MODULE_ABI_VERSION };

G_MODULE_EXPORT const GeglModuleInfo *
gegl_module_query (GTypeModule *module G_GNUC_UNUSED)
{
  return &module_info;
}

G_MODULE_EXPORT gboolean
gegl_module_register (GTypeModule *module)
{
  /* Before the classes are set up: their labels are translated then. */
  ts_op_bind_textdomain ();
  gegl_op_texsynth_volume_slice_register_type (module);
  gegl_op_texsynth_volume_save_register_type (module);
  return TRUE;
}
