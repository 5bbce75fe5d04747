/* Built cases of texture by numbers (see guided-cases.h).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "guided-cases.h"
#include "guided-metrics.h"
#include "metrics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *const ts_case_layout_name[TS_CASE_LAYOUTS] = { "discs", "stripes", "lines" };

uint8_t
ts_case_target_label (TsCaseLayout layout, size_t x, size_t y)
{
  switch (layout)
    {
    case TS_CASE_DISCS:
      {
        double dx = (double) (x % 80) - 40.0, dy = (double) (y % 80) - 40.0;
        return dx * dx + dy * dy < 26.0 * 26.0 ? (uint8_t) (1 + (x / 80 + y / 80) % 2) : 0;
      }
    case TS_CASE_STRIPES:
      return (uint8_t) ((y / 24) % 3);
    case TS_CASE_LINES:
      /* 10-pixel slanted lines of labels 1 and 2 on 0. */
      return ((x + y / 2) % 40) < 10 ? (uint8_t) (1 + (x + y / 2) / 40 % 2) : 0;
    case TS_CASE_LAYOUTS:
      break;
    }
  return 0;
}

bool
ts_case_exemplar (const TsImage texture[3], TsImage *exemplar, uint8_t *labels)
{
  for (size_t l = 0; l < 3; l++)
    if (texture[l].width < TS_CASE_STRIP || texture[l].height < TS_CASE_EX_H)
      return false;
  exemplar->width = TS_CASE_EX_W;
  exemplar->height = TS_CASE_EX_H;
  exemplar->pixels = malloc (TS_CASE_EX_W * TS_CASE_EX_H * TS_CHANNELS * sizeof (float));
  if (!exemplar->pixels)
    return false;
  for (size_t l = 0; l < 3; l++)
    for (size_t y = 0; y < TS_CASE_EX_H; y++)
      for (size_t x = 0; x < TS_CASE_STRIP; x++)
        {
          memcpy (exemplar->pixels + (y * TS_CASE_EX_W + l * TS_CASE_STRIP + x) * TS_CHANNELS,
                  texture[l].pixels + (y * texture[l].width + x) * TS_CHANNELS,
                  TS_CHANNELS * sizeof (float));
          labels[y * TS_CASE_EX_W + l * TS_CASE_STRIP + x] = (uint8_t) l;
        }
  return true;
}

bool
ts_case_strip (const TsImage *exemplar, size_t l, TsImage *strip)
{
  strip->width = TS_CASE_STRIP;
  strip->height = TS_CASE_EX_H;
  strip->pixels = malloc (TS_CASE_STRIP * TS_CASE_EX_H * TS_CHANNELS * sizeof (float));
  if (!strip->pixels)
    return false;
  for (size_t y = 0; y < TS_CASE_EX_H; y++)
    memcpy (strip->pixels + y * TS_CASE_STRIP * TS_CHANNELS,
            exemplar->pixels + (y * TS_CASE_EX_W + l * TS_CASE_STRIP) * TS_CHANNELS,
            TS_CASE_STRIP * TS_CHANNELS * sizeof (float));
  return true;
}

/* A caller's number of seeds, within 1..TS_CASE_MAX_SEEDS. */
static size_t
seed_count (size_t seeds)
{
  return seeds < 1 ? 1 : seeds > TS_CASE_MAX_SEEDS ? TS_CASE_MAX_SEEDS : seeds;
}

double
ts_case_median (const double *v, size_t n)
{
  double sorted[TS_CASE_MAX_SEEDS];

  n = seed_count (n);
  memcpy (sorted, v, n * sizeof (double));
  for (size_t i = 1; i < n; i++)
    for (size_t j = i; j > 0 && sorted[j - 1] > sorted[j]; j--)
      {
        double t = sorted[j];
        sorted[j] = sorted[j - 1];
        sorted[j - 1] = t;
      }
  return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

static TsStatus
synthesize (const TsImage *exemplar, const TsGuides *guides, uint32_t seed, TsImage *out,
            TsError *error)
{
  TsParams p;

  ts_params_init (&p);
  p.output_width = out->width;
  p.output_height = out->height;
  p.seed = seed;
  p.guides = guides;
  return ts_synthesize (&p, exemplar, out, NULL, NULL, error);
}

TsStatus
ts_case_plain_coherence (const TsImage *exemplar, size_t l, size_t seeds, double *median,
                         TsError *error)
{
  TsImage strip = { 0 }, out = { TS_CASE_OUT, TS_CASE_OUT, NULL };
  double coherence[TS_CASE_MAX_SEEDS], seam;
  TsStatus status = TS_ERROR_OUT_OF_MEMORY;

  seeds = seed_count (seeds);

  out.pixels = malloc (TS_CASE_OUT * TS_CASE_OUT * TS_CHANNELS * sizeof (float));
  if (out.pixels && ts_case_strip (exemplar, l, &strip))
    {
      status = TS_OK;
      for (uint32_t s = 0; s < seeds && status == TS_OK; s++)
        {
          status = synthesize (&strip, NULL, TS_CASE_FIRST_SEED + s, &out, error);
          if (status == TS_OK)
            ts_measure_coherence (&strip, &out, false, false, &coherence[s], &seam);
        }
    }
  if (status == TS_OK)
    *median = ts_case_median (coherence, seeds);
  free (strip.pixels);
  free (out.pixels);
  return status;
}

TsStatus
ts_case_guided (const TsImage *exemplar, const uint8_t *labels, TsCaseLayout layout,
                bool blend_edges, size_t seeds, TsCaseFigures *figures, TsImage *first,
                TsError *error)
{
  size_t n = TS_CASE_OUT * TS_CASE_OUT;
  uint8_t *target = malloc (n);
  float *ex_guide = malloc (TS_CASE_EX_W * TS_CASE_EX_H * sizeof (float));
  float *t_guide = malloc (n * sizeof (float));
  TsImage out = { TS_CASE_OUT, TS_CASE_OUT, malloc (n * TS_CHANNELS * sizeof (float)) };
  TsStatus status = target && ex_guide && t_guide && out.pixels ? TS_OK : TS_ERROR_OUT_OF_MEMORY;
  TsGuides guides;

  if (status == TS_OK)
    {
      for (size_t i = 0; i < TS_CASE_EX_W * TS_CASE_EX_H; i++)
        ex_guide[i] = (float) labels[i] / 2.0f;
      for (size_t y = 0; y < TS_CASE_OUT; y++)
        for (size_t x = 0; x < TS_CASE_OUT; x++)
          {
            target[y * TS_CASE_OUT + x] = ts_case_target_label (layout, x, y);
            t_guide[y * TS_CASE_OUT + x] = (float) target[y * TS_CASE_OUT + x] / 2.0f;
          }
      ts_guides_init (&guides);
      guides.exemplar_guide = ex_guide;
      guides.target_guide = t_guide;
      guides.blend_edges = blend_edges;
    }
  seeds = seed_count (seeds);
  for (uint32_t s = 0; s < seeds && status == TS_OK; s++)
    {
      TsLabelMeasures m;
      status = synthesize (exemplar, &guides, TS_CASE_FIRST_SEED + s, &out, error);
      if (status != TS_OK)
        break;
      ts_measure_labels (exemplar, labels, &out, target, 3, &m);
      figures->fidelity[s] = m.fidelity;
      figures->offset[s] = m.edge_offset;
      for (size_t l = 0; l < 3; l++)
        figures->region[l][s] = m.region_coherence[l];
      if (s == 0 && first)
        memcpy (first->pixels, out.pixels, n * TS_CHANNELS * sizeof (float));
    }
  free (target);
  free (ex_guide);
  free (t_guide);
  free (out.pixels);
  return status;
}
