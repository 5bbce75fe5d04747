/* Solid texture sources: which exemplar pixel every voxel copies, and
 * laying out aligned maps (a material's roughness, height ...) with them.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"
#include "engine/error.h"

#include <string.h>

TsStatus
ts_synthesize_solid (const TsSolidParams *params, const TsImage *const exemplars[3], float *volume,
                     TsProgressFunc progress, void *user_data, TsError *error)
{
  TsSolidParams plain;

  if (!params)
    return ts_synthesize_solid_with_sources (params, exemplars, volume, NULL, progress,
                                             user_data, error);
  /* Not recording costs nothing: no buffer, no memory counted. */
  plain = *params;
  plain.record_sources = false;
  return ts_synthesize_solid_with_sources (&plain, exemplars, volume, NULL, progress, user_data,
                                           error);
}

TsStatus
ts_solid_apply_sources (const TsSolidSource *sources, size_t voxels, const void *const maps[3],
                        const size_t map_pixels[3], size_t pixel_bytes, void *out,
                        TsError *error)
{
  static const char *const axis_names[3] = { "x", "y", "z" };
  unsigned char *to = out;

  if (!sources || !maps || !map_pixels || !out || pixel_bytes == 0)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no sources, maps or output given");
  /* Checked first, so that a bad source leaves `out` untouched. */
  for (size_t p = 0; p < voxels; p++)
    {
      int axis = ts_solid_source_axis (sources[p]);
      if (axis > 2 || !maps[axis])
        return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                        "voxel %zu copies the exemplar of the slices across %s, which has no map",
                        p, axis > 2 ? "?" : axis_names[axis]);
      if (ts_solid_source_index (sources[p]) >= map_pixels[axis])
        return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                        "voxel %zu copies pixel %u of the exemplar of the slices across %s, "
                        "but its map has only %zu pixels", p, ts_solid_source_index (sources[p]),
                        axis_names[axis], map_pixels[axis]);
    }
#pragma omp parallel for schedule(static) if (voxels >= 32768)
  for (ptrdiff_t p = 0; p < (ptrdiff_t) voxels; p++)
    {
      TsSolidSource s = sources[p];
      const unsigned char *from = maps[ts_solid_source_axis (s)];
      memcpy (to + (size_t) p * pixel_bytes, from + (size_t) ts_solid_source_index (s) * pixel_bytes,
              pixel_bytes);
    }
  return TS_OK;
}
