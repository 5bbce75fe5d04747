/* Synthesis properties both volume ops share, in gegl-op.h's property
 * "chant" (see synthesis-properties.h; the solid engine has no fine patch
 * size). Included inside each op's GEGL_PROPERTIES block, which gegl-op.h
 * expands several times: so no include guard. Enums are not here: each
 * op must register its own enum types.
 * SPDX-License-Identifier: LGPL-3.0-or-later */

property_int (size, _("Size"), (int) ts_volume_op_default_params ().size)
  description (_("Edge of the cube in voxels: the volume has size^3 voxels "
                 "and every slice is size x size pixels"))
  value_range (TS_SOLID_MIN_SIZE, TS_VOLUME_OP_MAX_SIZE)
  ui_range    (TS_SOLID_MIN_SIZE, 256)

property_boolean (periodic, _("Periodic"), ts_volume_op_default_params ().periodic)
  description (_("The volume repeats seamlessly in x, y and z, so every "
                 "slice tiles"))

property_int (quality, _("Quality"), ts_volume_op_default_params ().quality)
  description (_("Search breadth per voxel and orientation (3 x quality "
                 "tree leaves): higher searches more and is slower"))
  value_range (TS_MIN_QUALITY, TS_MAX_QUALITY)

property_seed (seed, _("Random seed"), rand)
  description (_("The same seed with the same settings gives the same "
                 "volume, whatever the number of threads"))

property_int (patch_size, _("Patch size"), ts_volume_op_default_params ().patch_size)
  description (_("Size in pixels of the neighbourhoods compared in each "
                 "slice orientation. 0 chooses automatically; even values "
                 "are rounded up to odd"))
  value_range (0, TS_MAX_PATCH_SIZE)
  ui_meta     ("role", "advanced")

property_int (iterations, _("Iterations"), ts_volume_op_default_params ().max_iterations)
  description (_("Maximum number of refinement iterations per level "
                 "(0 chooses automatically)"))
  value_range (0, TS_MAX_ITERATIONS)
  ui_range    (0, 20)
  ui_meta     ("role", "advanced")

property_boolean (histogram_matching, _("Histogram matching"),
                  ts_volume_op_default_params ().histogram_matching)
  description (_("Keep the colour distribution of the volume close to the "
                 "exemplars', so rare colours are neither lost nor overused"))
  ui_meta     ("role", "advanced")

/* An enum property whose type each op registers under its own name
 * (TS_VOLUME_OP_CELLS and TS_VOLUME_OP_CELLS_NAME, defined before this
 * file is included): gegl-op.h pastes the name, so it is passed through
 * a macro of our own that expands it first. */
#ifndef TS_VOLUME_CELL_STRUCTURE_PROPERTY
#define TS_VOLUME_CELL_STRUCTURE_PROPERTY(enm, enum_name)                            \
  property_enum (cell_structure, _("Cell structure"), enm, enum_name,               \
                 ts_volume_op_default_params ().cell_structure)                     \
    description (_("For exemplars of cells, such as stones in mortar, cobbles "     \
                   "or cracked mud: a 3D tessellation fitted to the exemplar "      \
                   "decides where the walls between cells go, so every slice "      \
                   "shows whole cells with closed joints. Automatic turns it on "   \
                   "for opaque exemplars of separate light stones in thin dark "    \
                   "joints that run every way, not in rows as tiles and bricks; "   \
                   "On needs an opaque exemplar"))
#endif
TS_VOLUME_CELL_STRUCTURE_PROPERTY (TS_VOLUME_OP_CELLS, TS_VOLUME_OP_CELLS_NAME)

property_int (memory_limit, _("Memory limit (MiB)"), 0)
  description (_("Refuse, with a message saying how much it would need, a "
                 "synthesis that needs more memory than this; 0 means a "
                 "quarter of the RAM (at least 1 GiB)"))
  value_range (0, G_MAXINT)
  ui_range    (0, 65536)
  ui_meta     ("role", "advanced")
