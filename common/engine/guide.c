/* Guides down the pyramid, the exemplar grouped by guide, and the
 * guided start and proposals.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "guide.h"
#include "guide-style.h"
#include "indexing.h"
#include "rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The smallest spread of a value guide the cost divides by: a hundredth
 * of its range, so a nearly flat exemplar guide does not make every
 * small difference decisive. */
#define TS_GUIDE_MIN_SPREAD 1e-4

static TsStatus
label_plane_alloc (TsGuidePlane *plane, size_t width, size_t height)
{
  plane->width = width;
  plane->height = height;
  plane->label = malloc (width * height);
  return plane->label ? TS_OK : TS_ERROR_OUT_OF_MEMORY;
}

/* The most common label of each 2x2 block (the first on ties): a label
 * keeps its region at a coarser level instead of a blend of labels. */
static TsStatus
reduce_labels (const TsGuidePlane *in, TsGuidePlane *out)
{
  TsStatus status = label_plane_alloc (out, (in->width + 1) / 2, (in->height + 1) / 2);
  if (status != TS_OK)
    return status;
  for (size_t y = 0; y < out->height; y++)
    for (size_t x = 0; x < out->width; x++)
      {
        uint8_t l[4];
        size_t best = 0, best_n = 0;
        for (size_t i = 0; i < 4; i++)
          {
            size_t sx = 2 * x + (i & 1), sy = 2 * y + i / 2;
            sx = sx < in->width ? sx : in->width - 1;
            sy = sy < in->height ? sy : in->height - 1;
            l[i] = in->label[sy * in->width + sx];
          }
        for (size_t i = 0; i < 4; i++)
          {
            size_t n = 0;
            for (size_t j = 0; j < 4; j++)
              n += l[j] == l[i];
            if (n > best_n)
              {
                best_n = n;
                best = i;
              }
          }
        out->label[y * out->width + x] = l[best];
      }
  return TS_OK;
}

static TsStatus
build_labels (const TsGuides *g, const TsImage *exemplar, size_t out_w, size_t out_h,
              TsGuidePyramid *guides)
{
  float table[TS_MAX_GUIDE_LABELS * TS_MAX_GUIDE_CHANNELS];
  size_t count, ex_n = exemplar->width * exemplar->height;
  TsStatus status;

  if (!ts_guide_find_labels (g->exemplar_guide, ex_n, g->channels, table, TS_MAX_GUIDE_LABELS,
                             &count))
    return TS_ERROR_BAD_PARAMETER;
  guides->label_count = count;
  status = label_plane_alloc (&guides->exemplar[0], exemplar->width, exemplar->height);
  if (status == TS_OK)
    status = label_plane_alloc (&guides->target[0], out_w, out_h);
  if (status != TS_OK)
    return status;
  for (size_t i = 0; i < ex_n; i++)
    guides->exemplar[0].label[i] =
      ts_guide_nearest_label (table, count, g->channels, g->exemplar_guide + i * g->channels);
  /* A target value between labels (a smoothed edge) takes the nearest. */
#pragma omp parallel for schedule(static)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) (out_w * out_h); i++)
    guides->target[0].label[i] =
      ts_guide_nearest_label (table, count, g->channels, g->target_guide + (size_t) i * g->channels);
  for (size_t l = 1; l < guides->levels && status == TS_OK; l++)
    {
      status = reduce_labels (&guides->exemplar[l - 1], &guides->exemplar[l]);
      if (status == TS_OK)
        status = reduce_labels (&guides->target[l - 1], &guides->target[l]);
    }
  return status;
}

static TsStatus
value_pyramid (const TsImage *base, TsGuidePlane *planes, size_t levels)
{
  TsPyramid pyramid;
  TsStatus status = ts_pyramid_build (base, levels, &pyramid);

  if (status != TS_OK)
    return status;
  for (size_t l = 0; l < levels; l++)
    {
      TsImage *v = &pyramid.level[l];
      /* Channel 3 only weighted the reduction; distances skip it. */
      for (size_t i = 0; i < ts_image_pixel_count (v); i++)
        v->pixels[i * TS_CHANNELS + 3] = 0.0f;
      planes[l].width = v->width;
      planes[l].height = v->height;
      planes[l].value = *v;
    }
  free (pyramid.level);
  return TS_OK;
}

static TsStatus
build_values (const TsGuides *g, const TsImage *exemplar, size_t out_w, size_t out_h,
              TsGuidePyramid *guides)
{
  size_t ex_n = exemplar->width * exemplar->height, out_n = out_w * out_h, ch = g->channels;
  TsImage ex_base = { 0 }, target_base = { 0 };
  TsStatus status = ts_image_alloc (&ex_base, exemplar->width, exemplar->height);

  if (status == TS_OK)
    status = ts_image_alloc (&target_base, out_w, out_h);
  if (status != TS_OK)
    {
      ts_image_free (&ex_base);
      return status;
    }
  for (size_t i = 0; i < ex_n; i++)
    {
      float *p = ex_base.pixels + i * TS_CHANNELS;
      for (size_t c = 0; c < ch; c++)
        p[c] = g->exemplar_guide ? g->exemplar_guide[i * ch + c]
                                 : exemplar->pixels[i * TS_CHANNELS] / 100.0f;
      p[3] = 1.0f;
    }
  for (size_t i = 0; i < out_n; i++)
    {
      float *p = target_base.pixels + i * TS_CHANNELS;
      for (size_t c = 0; c < ch; c++)
        p[c] = g->target_guide[i * ch + c];
      p[3] = 1.0f;
    }
  /* Style transfer compares the layout's tones and the grain's
   * strength, not the grain itself: that is the exemplar's to give. */
  if (!g->exemplar_guide)
    status = ts_style_guides (exemplar, &ex_base, &target_base);
  /* Bins run over the exemplar guide's channel mean (a style guide's
   * tone alone). */
  guides->bin_low = INFINITY;
  guides->bin_high = -INFINITY;
  for (size_t i = 0; i < ex_n; i++)
    {
      float key = 0.0f;
      for (size_t c = 0; c < guides->bin_channels; c++)
        key += ex_base.pixels[i * TS_CHANNELS + c];
      key /= (float) guides->bin_channels;
      guides->bin_low = fminf (guides->bin_low, key);
      guides->bin_high = fmaxf (guides->bin_high, key);
    }
  if (status == TS_OK)
    status = value_pyramid (&ex_base, guides->exemplar, guides->levels);
  if (status == TS_OK)
    status = value_pyramid (&target_base, guides->target, guides->levels);
  ts_image_free (&ex_base);
  ts_image_free (&target_base);
  return status;
}

TsStatus
ts_guide_planes_alloc (TsGuidePyramid *guides, size_t levels)
{
  guides->exemplar = calloc (levels, sizeof (TsGuidePlane));
  guides->target = calloc (levels, sizeof (TsGuidePlane));
  if (!guides->exemplar || !guides->target)
    {
      free (guides->exemplar);
      free (guides->target);
      guides->exemplar = guides->target = NULL;
      return TS_ERROR_OUT_OF_MEMORY;
    }
  guides->levels = levels;
  return TS_OK;
}

TsStatus
ts_guide_pyramid_build (const TsParams *params, const TsImage *exemplar,
                        const TsPyramid *pyramid, TsGuidePyramid *guides)
{
  const TsGuides *g = params->guides;
  TsStatus status;

  memset (guides, 0, sizeof *guides);
  guides->labels = ts_guides_use_labels (params, exemplar);
  guides->style = !g->exemplar_guide;
  guides->weight = g->weight;
  guides->channels = guides->style ? TS_STYLE_GUIDE_CHANNELS : g->channels;
  guides->bin_channels = guides->style ? 1 : g->channels;
  if (ts_guide_planes_alloc (guides, pyramid->levels) != TS_OK)
    return TS_ERROR_OUT_OF_MEMORY;
  status = guides->labels
             ? build_labels (g, exemplar, params->output_width, params->output_height, guides)
             : build_values (g, exemplar, params->output_width, params->output_height, guides);
  if (status != TS_OK)
    ts_guide_pyramid_free (guides);
  return status;
}

static void
plane_free (TsGuidePlane *plane)
{
  free (plane->label);
  ts_image_free (&plane->value);
}

void
ts_guide_pyramid_free (TsGuidePyramid *guides)
{
  for (size_t l = 0; l < guides->levels; l++)
    {
      if (guides->exemplar)
        plane_free (&guides->exemplar[l]);
      if (guides->target)
        plane_free (&guides->target[l]);
    }
  free (guides->exemplar);
  free (guides->target);
  memset (guides, 0, sizeof *guides);
}

/* A lattice guide's bin is its phase cell: each period's phase (a
 * cosine and sine pair) cut into TS_LATTICE_PHASE_BINS steps. */
static size_t
bin_of_phases (const TsGuideLevel *g, const float *v)
{
  size_t bin = 0;

  for (size_t k = 0; 2 * k < g->channels; k++)
    {
      float turn = atan2f (v[2 * k + 1], v[2 * k]) / 6.2831853f + 0.5f;
      size_t step = (size_t) (turn * (float) TS_LATTICE_PHASE_BINS);
      bin = bin * TS_LATTICE_PHASE_BINS + (step < TS_LATTICE_PHASE_BINS ? step : 0);
    }
  return bin;
}

static size_t
bin_of_values (const TsGuideLevel *g, const float *v)
{
  float key = 0.0f, bin;

  if (g->lattice)
    return bin_of_phases (g, v);
  for (size_t c = 0; c < g->bin_channels; c++)
    key += v[c];
  bin = (key / (float) g->bin_channels - g->bin_low) * g->bin_scale;
  if (!(bin > 0.0f))
    return 0;
  return bin >= (float) g->bins ? g->bins - 1 : (size_t) bin;
}

size_t
ts_guide_target_bin (const TsGuideLevel *g, size_t x, size_t y)
{
  size_t b = g->labels ? g->target->label[y * g->target->width + x]
                       : bin_of_values (g, ts_image_pixel (&g->target->value, x, y));
  return g->bin_nearest[b];
}

/* Variance of the colours (L, a, b summed) of the opaque pixels of `ex`. */
static double
colour_variance (const TsImage *ex)
{
  double mean[3] = { 0, 0, 0 }, var = 0.0, n = 0.0;
  size_t count = ts_image_pixel_count (ex);

  for (size_t i = 0; i < count; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] > 0.0f)
      {
        for (int c = 0; c < 3; c++)
          mean[c] += ex->pixels[i * TS_CHANNELS + c];
        n += 1.0;
      }
  if (n == 0.0)
    return 0.0;
  for (int c = 0; c < 3; c++)
    mean[c] /= n;
  for (size_t i = 0; i < count; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] > 0.0f)
      for (int c = 0; c < 3; c++)
        {
          double d = ex->pixels[i * TS_CHANNELS + c] - mean[c];
          var += d * d;
        }
  return var / n;
}

/* Summed variance of the value guide's `channels` over `ex`'s opaque pixels. */
static double
guide_variance (const TsImage *guide, size_t channels, const TsImage *ex)
{
  double var = 0.0;
  for (size_t c = 0; c < channels; c++)
    {
      double mean, sd;
      ts_guide_spread (guide->pixels + c, TS_CHANNELS, ts_image_pixel_count (guide), ex->pixels + 3, &mean,
              &sd);
      var += sd * sd;
    }
  return var;
}

TsStatus
ts_guide_level_init (const TsGuidePyramid *guides, size_t level, const TsImage *ex,
                     TsGuideLevel *out)
{
  size_t n = ts_image_pixel_count (ex), *count;
  double colour_var = colour_variance (ex);

  memset (out, 0, sizeof *out);
  out->exemplar = &guides->exemplar[level];
  out->target = &guides->target[level];
  out->labels = guides->labels;
  out->lattice = guides->lattice;
  out->proposals = guides->lattice ? TS_LATTICE_PROPOSALS
                  : guides->style && level == 0 ? TS_STYLE_FINEST_PROPOSALS : TS_GUIDE_PROPOSALS;
  out->channels = guides->channels;
  out->bin_channels = guides->bin_channels;
  out->centre_only = guides->lattice || guides->style;
  /* A disagreeing guide pixel costs `weight` times the expected squared
   * difference of two unrelated texture pixels (twice the variance);
   * value differences are counted in the same units through the guide's
   * own spread. */
  if (guides->labels)
    {
      out->cost = (float) (guides->weight * 2.0 * colour_var);
      out->bins = guides->label_count;
      out->vote_mismatch = (float) exp (-TS_GUIDE_VOTE_SHARPNESS * guides->weight);
    }
  else
    {
      /* A style guide's contrast is scaled to its tone's spread. */
      double guide_var =
        guide_variance (&out->exemplar->value, guides->style ? 1 : out->channels, ex);
      guide_var = guide_var > TS_GUIDE_MIN_SPREAD ? guide_var : TS_GUIDE_MIN_SPREAD;
      out->cost = (float) (guides->weight * colour_var / guide_var);
      /* A difference as large as two unrelated guide values' costs what
       * a disagreeing label does. */
      out->vote_scale = (float) ((guides->style ? TS_STYLE_VOTE_SHARPNESS : TS_GUIDE_VOTE_SHARPNESS)
                                 * guides->weight / (2.0 * guide_var));
      if (guides->style)
        out->cost *= (float) (level == 0 ? TS_STYLE_FINEST_WEIGHT : TS_STYLE_COARSE_WEIGHT);
      out->bins = TS_GUIDE_VALUE_BINS;
      if (out->lattice)
        out->bins = out->channels == 4 ? TS_LATTICE_PHASE_BINS * TS_LATTICE_PHASE_BINS
                                       : TS_LATTICE_PHASE_BINS;
      out->bin_low = guides->bin_low;
      out->bin_scale = guides->bin_high > guides->bin_low
                         ? (float) out->bins / (guides->bin_high - guides->bin_low) : 0.0f;
    }
  if (!guides->labels)
    {
      size_t ch = out->channels;
      out->packed = malloc ((n ? n : 1) * ch * sizeof (float));
      if (!out->packed)
        {
          ts_guide_level_free (out);
          return TS_ERROR_OUT_OF_MEMORY;
        }
      for (size_t i = 0; i < n; i++)
        memcpy (out->packed + i * ch, out->exemplar->value.pixels + i * TS_CHANNELS,
                ch * sizeof (float));
    }
  out->bin_start = calloc (out->bins + 1, sizeof (size_t));
  out->bin_nearest = malloc (out->bins * sizeof (size_t));
  count = calloc (out->bins, sizeof (size_t));
  out->bin_member = malloc ((n ? n : 1) * sizeof (int32_t));
  if (!out->bin_start || !out->bin_nearest || !count || !out->bin_member)
    {
      free (count);
      ts_guide_level_free (out);
      return TS_ERROR_OUT_OF_MEMORY;
    }
  for (size_t i = 0; i < n; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] > 0.0f)
      count[out->labels ? out->exemplar->label[i]
                        : bin_of_values (out, out->exemplar->value.pixels + i * TS_CHANNELS)]++;
  for (size_t b = 0; b < out->bins; b++)
    out->bin_start[b + 1] = out->bin_start[b] + count[b];
  memset (count, 0, out->bins * sizeof (size_t));
  for (size_t i = 0; i < n; i++)
    if (ex->pixels[i * TS_CHANNELS + 3] > 0.0f)
      {
        size_t b = out->labels ? out->exemplar->label[i]
                               : bin_of_values (out, out->exemplar->value.pixels + i * TS_CHANNELS);
        out->bin_member[out->bin_start[b] + count[b]++] = (int32_t) i;
      }
  free (count);
  /* A bin without exemplar pixels borrows the nearest one with some (a
   * label whose region vanished at this level, a value the exemplar
   * lacks). The exemplar has an opaque pixel, so one exists. */
  for (size_t b = 0; b < out->bins; b++)
    {
      size_t best = b;
      for (size_t d = 0; d < out->bins && out->bin_start[best + 1] == out->bin_start[best]; d++)
        {
          if (b >= d && out->bin_start[b - d + 1] > out->bin_start[b - d])
            best = b - d;
          else if (b + d < out->bins && out->bin_start[b + d + 1] > out->bin_start[b + d])
            best = b + d;
        }
      out->bin_nearest[b] = best;
    }
  return TS_OK;
}

void
ts_guide_wanted_usage (const TsGuideLevel *g, const TsImage *ex, float *wanted)
{
  size_t n = ts_image_pixel_count (ex), target_n = g->target->width * g->target->height;
  size_t *in_target = calloc (g->bins, sizeof (size_t));

  if (!in_target)
    {
      /* Without the counts every pixel is wanted alike: plain matching. */
      for (size_t i = 0; i < n; i++)
        wanted[i] = 1.0f;
      return;
    }
  for (size_t y = 0; y < g->target->height; y++)
    for (size_t x = 0; x < g->target->width; x++)
      in_target[ts_guide_target_bin (g, x, y)]++;
  for (size_t i = 0; i < n; i++)
    {
      size_t b;
      wanted[i] = 0.0f;
      if (ex->pixels[i * TS_CHANNELS + 3] <= 0.0f)
        continue;
      b = g->labels ? g->exemplar->label[i]
                    : bin_of_values (g, g->exemplar->value.pixels + i * TS_CHANNELS);
      wanted[i] = (float) ((double) in_target[b] / (double) target_n * (double) n /
                           (double) (g->bin_start[b + 1] - g->bin_start[b]));
    }
  free (in_target);
}

void
ts_guide_level_free (TsGuideLevel *level)
{
  free (level->bin_start);
  free (level->bin_member);
  free (level->bin_nearest);
  free (level->packed);
  memset (level, 0, sizeof *level);
}

void
ts_guide_start_blocks (const TsGuideLevel *g, const TsImage *ex, int32_t *source, size_t width,
                       size_t height, uint32_t seed, size_t level, size_t block)
{
  uint64_t jitter = ts_random (seed, (uint32_t) level, 0, 0, 4);
  size_t ox = (size_t) (jitter % block), oy = (size_t) ((jitter >> 32) % block);

#pragma omp parallel for schedule(static)
  for (ptrdiff_t y = 0; y < (ptrdiff_t) height; y++)
    for (size_t x = 0; x < width; x++)
      {
        size_t bx = (x + ox) / block, by = ((size_t) y + oy) / block;
        size_t bin = ts_guide_target_bin (g, x, (size_t) y);
        size_t members = g->bin_start[bin + 1] - g->bin_start[bin];
        /* Pixels of one block and one guide share a corner: the start
         * copies pieces of the right texture, not single pixels. */
        uint64_t r = ts_random (seed, (uint32_t) level, 0,
                                (by * 65536 + bx) * g->bins + bin, 6);
        int32_t corner = g->bin_member[g->bin_start[bin] + ts_random_below (r, members)];
        size_t sx = (size_t) corner % ex->width + (x + ox) % block;
        size_t sy = (size_t) corner / ex->width + ((size_t) y + oy) % block;
        int32_t s;

        sx = sx < ex->width ? sx : ex->width - 1 - (sx - ex->width) % ex->width;
        sy = sy < ex->height ? sy : ex->height - 1 - (sy - ex->height) % ex->height;
        s = (int32_t) (sy * ex->width + sx);
        if (ex->pixels[(size_t) s * TS_CHANNELS + 3] <= 0.0f)
          s = corner;
        source[(size_t) y * width + x] = s;
      }
}

TsStatus
ts_guide_query_init (TsGuideQuery *q, const TsGuideLevel *level, size_t patch)
{
  memset (q, 0, sizeof *q);
  q->level = level;
  q->patch = patch;
  q->radius = patch / 2;
  if (level->labels)
    q->labels = malloc (patch * patch);
  else
    q->values = malloc (patch * patch * level->channels * sizeof (float));
  return q->labels || q->values ? TS_OK : TS_ERROR_OUT_OF_MEMORY;
}

void
ts_guide_query_free (TsGuideQuery *q)
{
  free (q->labels);
  free (q->values);
  q->labels = NULL;
  q->values = NULL;
}

void
ts_guide_query_gather (TsGuideQuery *q, ptrdiff_t cx, ptrdiff_t cy, bool wrap_x, bool wrap_y)
{
  const TsGuidePlane *t = q->level->target;
  ptrdiff_t r = (ptrdiff_t) q->radius;
  size_t i = 0;

  if (q->level->centre_only)
    {
      /* ts_guide_cost reads a lattice or style guide's centre alone */
      memcpy (q->values + (q->radius * q->patch + q->radius) * q->level->channels,
              ts_image_pixel (&t->value, (size_t) cx, (size_t) cy),
              q->level->channels * sizeof (float));
      return;
    }
  for (ptrdiff_t dy = -r; dy <= r; dy++)
    {
      size_t y = ts_border_index (cy + dy, t->height, wrap_y);
      for (ptrdiff_t dx = -r; dx <= r; dx++, i++)
        {
          size_t x = ts_border_index (cx + dx, t->width, wrap_x);
          if (q->labels)
            q->labels[i] = t->label[y * t->width + x];
          else
            memcpy (q->values + i * q->level->channels, ts_image_pixel (&t->value, x, y),
                    q->level->channels * sizeof (float));
        }
    }
}
