/* Properties both texsynth ops share, in gegl-op.h's property "chant".
 * Included inside each op's GEGL_PROPERTIES block, which gegl-op.h expands
 * several times with different macro definitions: so no include guard.
 * SPDX-License-Identifier: LGPL-3.0-or-later */

property_int (quality, _("Quality"), ts_op_default_params ().quality)
  description (_("Candidates compared per pixel (k = quality + 1): higher "
                 "searches more and is slower; 2 measured best on average"))
  value_range (TS_MIN_QUALITY, TS_MAX_QUALITY)

property_seed (seed, _("Random seed"), rand)
  description (_("The same seed with the same settings gives the same "
                 "result, whatever the number of threads; change it for "
                 "another variation"))

property_int (patch_size, _("Patch size"), ts_op_default_params ().patch_size)
  description (_("Size in pixels of the neighbourhoods compared in the "
                 "first iterations of each level; larger keeps larger "
                 "structures together. 0 chooses automatically; even "
                 "values are rounded up to odd"))
  value_range (0, TS_MAX_PATCH_SIZE)
  ui_meta     ("role", "advanced")

property_int (fine_patch_size, _("Fine patch size"), ts_op_default_params ().fine_patch_size)
  description (_("Size in pixels of the neighbourhoods of the last "
                 "iterations, at most the patch size; smaller gives "
                 "sharper detail. 0 chooses automatically; even values "
                 "are rounded up to odd"))
  value_range (0, TS_MAX_PATCH_SIZE)
  ui_meta     ("role", "advanced")

property_int (iterations, _("Iterations"), ts_op_default_params ().max_iterations)
  description (_("Maximum number of refinement iterations per level "
                 "(0 chooses automatically)"))
  value_range (0, TS_MAX_ITERATIONS)
  ui_range    (0, 20)
  ui_meta     ("role", "advanced")

property_boolean (histogram_matching, _("Histogram matching"),
                  ts_op_default_params ().histogram_matching)
  description (_("Keep the colour distribution of the result close to the "
                 "input's, so rare colours are neither lost nor overused"))
  ui_meta     ("role", "advanced")

property_int (memory_limit, _("Memory limit (MiB)"), 0)
  description (_("Refuse, with a message saying how much it would need, a "
                 "synthesis that needs more memory than this; 0 means a "
                 "quarter of the RAM (at least 1 GiB)"))
  value_range (0, G_MAXINT)
  ui_range    (0, 65536)
  ui_meta     ("role", "advanced")

property_boolean (source_map, _("Source map"), FALSE)
  description (_("Output the layout instead of colours: for each pixel, the "
                 "absolute coordinates of the input pixel it comes from, in "
                 "the first two channels of a float image. gegl:map-absolute "
                 "with sampler-type nearest applies this layout to any map "
                 "aligned with the input (normal, roughness, height)"))
  /* Hidden from GIMP's generated dialog (the GUM "visible" key, which
   * GIMP's property GUI evaluates), where the coordinates would show as a
   * strange two-channel picture; gegl, XML and scripts still set it, and
   * GIMP users get layouts through Texture Synthesis of All Layers. */
  ui_meta     ("visible", "0")
