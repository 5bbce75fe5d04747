/* SPDX-License-Identifier: LGPL-3.0-or-later */
#include "slice-figures.h"
#include "metrics.h"
#include "truth-solids.h"
#include "../operations/lab-arithmetic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The truth solids are drawn in sRGB with its own D65 white (no
 * adaptation to the ops' D50: the truth and its slices are compared only
 * with each other and with solids synthesised from them). */
static const double d65[3] = { 0.95047, 1.0, 1.08883 };

void
slice_rgb8_to_lab (const uint8_t *rgb, size_t count, float *lab)
{
  for (size_t i = 0; i < count; i++)
    {
      double r = ts_srgb_to_linear (rgb[3 * i] / 255.0);
      double g = ts_srgb_to_linear (rgb[3 * i + 1] / 255.0);
      double b = ts_srgb_to_linear (rgb[3 * i + 2] / 255.0);
      double xyz[3] = { 0.4124 * r + 0.3576 * g + 0.1805 * b,
                        0.2126 * r + 0.7152 * g + 0.0722 * b,
                        0.0193 * r + 0.1192 * g + 0.9505 * b };
      ts_xyz_to_lab (xyz, d65, lab + 4 * i);
      lab[4 * i + 3] = 1.0f;
    }
}

float *
slice_truth_lab (const char *name, size_t n, uint32_t seed)
{
  uint8_t *rgb = malloc (n * n * n * 3);
  float *lab = malloc (n * n * n * TS_CHANNELS * sizeof (float));

  if (rgb && lab && truth_solid_render (name, n, seed, rgb))
    slice_rgb8_to_lab (rgb, n * n * n, lab);
  else
    {
      free (lab);
      lab = NULL;
    }
  free (rgb);
  return lab;
}

void
slice_cut (const float *volume, size_t n, int axis, size_t index, TsImage *out)
{
  for (size_t v = 0; v < n; v++)
    for (size_t u = 0; u < n; u++)
      {
        float *o = out->pixels + (v * n + u) * TS_CHANNELS;
        if (axis < 3)
          {
            size_t x = axis == 0 ? index : u, y = axis == 1 ? index : (axis == 0 ? u : v);
            size_t z = axis == 2 ? index : v;
            memcpy (o, volume + ((z * n + y) * n + x) * TS_CHANNELS, TS_CHANNELS * sizeof (float));
            continue;
          }
        double s = (double) u / sqrt (2.0), f = floor (s), t = s - f;
        double w[4] = { (1 - t) * (1 - t), t * (1 - t), (1 - t) * t, t * t };
        for (int c = 0; c < TS_CHANNELS; c++)
          o[c] = 0.0f;
        for (int k = 0; k < 4; k++)
          {
            size_t x = ((size_t) f + (size_t) (k & 1)) % n, z = ((size_t) f + (size_t) (k >> 1)) % n;
            const float *p = volume + ((z * n + v) * n + x) * TS_CHANNELS;
            for (int c = 0; c < TS_CHANNELS; c++)
              o[c] += (float) (w[k] * p[c]);
          }
      }
}

static double
median4 (const double a[SLICE_KINDS])
{
  double s[SLICE_KINDS];
  memcpy (s, a, sizeof s);
  for (int i = 0; i < SLICE_KINDS; i++)
    for (int j = i + 1; j < SLICE_KINDS; j++)
      if (s[j] < s[i])
        {
          double t = s[i];
          s[i] = s[j];
          s[j] = t;
        }
  return 0.5 * (s[1] + s[2]);
}

bool
slice_figures (const TsImage *exemplar, const float *volume, size_t n, SliceFigures *out)
{
  TsImage slice = { n, n, malloc (n * n * TS_CHANNELS * sizeof (float)) };
  double seams = 0.0;

  if (!slice.pixels)
    return false;
  out->worst_axis_edges = 0.0;
  for (int kind = 0; kind < SLICE_KINDS; kind++)
    {
      TsMeasures m;
      bool wrap = kind < 3; /* the diagonal plane does not tile at unit spacing */
      slice_cut (volume, n, kind, n / 2, &slice);
      if (ts_measure_all (exemplar, &slice, wrap, wrap, &m) != TS_MEASURE_OK)
        {
          free (slice.pixels);
          return false;
        }
      out->coherence[kind] = m.coherence;
      out->completeness[kind] = m.completeness;
      out->sharpness[kind] = m.sharpness;
      out->axis_edges[kind] = m.axis_edges;
      out->worst_axis_edges = fmax (out->worst_axis_edges, m.axis_edges);
    }
  for (int axis = 0; axis < 3; axis++)
    for (size_t k = 0; k < SLICE_SEAM_SLICES; k++)
      {
        double coherence, seam;
        slice_cut (volume, n, axis, (2 * k + 1) * n / (2 * SLICE_SEAM_SLICES), &slice);
        if (ts_measure_coherence (exemplar, &slice, true, true, &coherence, &seam) != TS_MEASURE_OK)
          {
            free (slice.pixels);
            return false;
          }
        seams += seam;
      }
  out->seam = seams / (3.0 * SLICE_SEAM_SLICES);
  out->all_slices_sharpness = 0.0;
  out->worst_slice_anisotropy = 0.0;
  for (int axis = 0; axis < 3; axis++)
    for (size_t k = 0; k < n; k++)
      {
        double sharpness, anisotropy;
        slice_cut (volume, n, axis, k, &slice);
        if (ts_measure_sharpness (exemplar, &slice, &sharpness) != TS_MEASURE_OK
            || ts_measure_anisotropy (&slice, &anisotropy) != TS_MEASURE_OK)
          {
            free (slice.pixels);
            return false;
          }
        out->all_slices_sharpness += sharpness / (3.0 * (double) n);
        /* A flat slice has no direction (NAN): fmax keeps the others'. */
        out->worst_slice_anisotropy = fmax (out->worst_slice_anisotropy, anisotropy);
      }
  out->median_coherence = median4 (out->coherence);
  out->median_completeness = median4 (out->completeness);
  out->median_sharpness = median4 (out->sharpness);
  out->median_axis_edges = median4 (out->axis_edges);
  free (slice.pixels);
  return true;
}
