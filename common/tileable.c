/* Making an existing image tileable by re-synthesising its edges
 * (ts_make_tileable); see tileable.h for the idea.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "tileable.h"
#include "image.h"
#include "schedule.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TS_TILEABLE_DEFAULT_SEAM_WIDTH 0.125
/* Preserve rises over this fraction of the narrower band, on both sides
 * of a join (and joins move inwards as far): wider is freer to heal, but
 * lets the optimization alter more of what was exact (0.7 gave
 * worse seams on the shared exemplars; 0.35 much the same). */
#define TS_TILEABLE_TRANSITION 0.5
#define TS_TILEABLE_FAR 1e20
/* Bounds the search for joins (and its memory) in huge images. */
#define TS_TILEABLE_MAX_REACH 256
/* Iterations per pass and level when the caller leaves them automatic:
 * only the pixels near the cuts are optimized, so more than a synthesis
 * uses are affordable; on the shared exemplars 6 heal the cuts as well as
 * 10 (coherence within 2%), 4 slightly worse. */
#define TS_TILEABLE_ITERATIONS 6

void
ts_tileable_params_init (TsTileableParams *params)
{
  TsParams defaults;

  ts_params_init (&defaults);
  memset (params, 0, sizeof *params);
  params->direction = TS_TILEABLE_BOTH;
  params->seam_width = TS_TILEABLE_DEFAULT_SEAM_WIDTH;
  params->quality = defaults.quality;
  params->seed = defaults.seed;
  params->patch_size = defaults.patch_size;
  params->fine_patch_size = defaults.fine_patch_size;
  params->max_iterations = defaults.max_iterations;
  params->histogram_matching = defaults.histogram_matching;
  params->memory_limit = defaults.memory_limit;
}

static bool
wraps_x (TsTileableDirection direction)
{
  return direction != TS_TILEABLE_VERTICAL;
}

static bool
wraps_y (TsTileableDirection direction)
{
  return direction != TS_TILEABLE_HORIZONTAL;
}

static void
fill_synthesis_params (const TsTileableParams *tp, const TsImage *input, TsParams *params)
{
  ts_params_init (params);
  params->output_width = input->width;
  params->output_height = input->height;
  params->wrap_x = wraps_x (tp->direction);
  params->wrap_y = wraps_y (tp->direction);
  params->quality = tp->quality;
  params->seed = tp->seed;
  params->patch_size = tp->patch_size;
  params->fine_patch_size = tp->fine_patch_size;
  params->max_iterations = tp->max_iterations ? tp->max_iterations : TS_TILEABLE_ITERATIONS;
  params->histogram_matching = tp->histogram_matching;
  params->memory_limit = tp->memory_limit;
}

static bool
has_opaque_pixel (const TsImage *image)
{
  size_t n = image->width * image->height;
  for (size_t i = 0; i < n; i++)
    if (image->pixels[i * TS_CHANNELS + 3] > 0.0f)
      return true;
  return false;
}

TsStatus
ts_tileable_params_validate (const TsTileableParams *params, const TsImage *input,
                             TsError *error)
{
  TsParams synthesis;

  if (!params || !input)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT, "no parameters or no input image given");
  if (params->direction != TS_TILEABLE_BOTH && params->direction != TS_TILEABLE_HORIZONTAL &&
      params->direction != TS_TILEABLE_VERTICAL)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "unknown direction %d", (int) params->direction);
  if (!(params->seam_width >= TS_TILEABLE_MIN_SEAM_WIDTH &&
        params->seam_width <= TS_TILEABLE_MAX_SEAM_WIDTH))
    return ts_fail (error, TS_ERROR_BAD_PARAMETER, "seam width must be %g to %g, got %g",
                    TS_TILEABLE_MIN_SEAM_WIDTH, TS_TILEABLE_MAX_SEAM_WIDTH, params->seam_width);
  if (input->width == 0 || input->height == 0 || !input->pixels)
    return ts_fail (error, TS_ERROR_EMPTY_EXEMPLAR, "the input has no pixels (%zux%zu)",
                    input->width, input->height);
  if ((wraps_x (params->direction) && input->width < TS_TILEABLE_MIN_SIDE) ||
      (wraps_y (params->direction) && input->height < TS_TILEABLE_MIN_SIDE) ||
      input->width < TS_MIN_PATCH_SIZE || input->height < TS_MIN_PATCH_SIZE)
    return ts_fail (error, TS_ERROR_EXEMPLAR_TOO_SMALL,
                    "the input is %zux%zu pixels, too small to make tileable: it needs at "
                    "least %d pixels along each direction that wraps (and %d along the other)",
                    input->width, input->height, TS_TILEABLE_MIN_SIDE, TS_MIN_PATCH_SIZE);
  if (input->width > TS_MAX_OUTPUT_SIDE || input->height > TS_MAX_OUTPUT_SIDE)
    return ts_fail (error, TS_ERROR_BAD_PARAMETER,
                    "the input is %zux%zu; its sides must be at most %d pixels",
                    input->width, input->height, TS_MAX_OUTPUT_SIDE);
  if (!has_opaque_pixel (input))
    return ts_fail (error, TS_ERROR_TRANSPARENT_EXEMPLAR,
                    "the input is fully transparent: there is nothing to make tileable");
  /* Quality, patch sizes, iterations and the memory estimate. */
  fill_synthesis_params (params, input, &synthesis);
  return ts_params_validate (&synthesis, input, error);
}

static size_t
band_for (double fraction, size_t side)
{
  size_t band = (size_t) lround (fraction * (double) side);
  size_t most = side / 4;

  if (band < 2)
    band = 2;
  return band < most ? band : most;
}

/* A join may move up to half the band towards the edge: the other half
 * keeps the shifted content unbroken across the wrap edge. */
static size_t
reach_for (size_t band)
{
  size_t reach = band / 2;
  return reach < TS_TILEABLE_MAX_REACH ? reach : TS_TILEABLE_MAX_REACH;
}

void
ts_tileable_plan_init (const TsTileableParams *params, const TsImage *input,
                       TsTileablePlan *plan)
{
  size_t narrow;

  memset (plan, 0, sizeof *plan);
  plan->width = input->width;
  plan->height = input->height;
  plan->wrap_x = wraps_x (params->direction);
  plan->wrap_y = wraps_y (params->direction);
  plan->band_x = plan->wrap_x ? band_for (params->seam_width, input->width) : 0;
  plan->band_y = plan->wrap_y ? band_for (params->seam_width, input->height) : 0;
  narrow = !plan->wrap_y ? plan->band_x
           : !plan->wrap_x ? plan->band_y
           : (plan->band_x < plan->band_y ? plan->band_x : plan->band_y);
  plan->transition = fmin (TS_TILEABLE_MAX_REACH,
                           fmax (2.0, TS_TILEABLE_TRANSITION * (double) narrow));
  plan->reach_x = reach_for (plan->band_x);
  plan->reach_y = reach_for (plan->band_y);
}

void
ts_tileable_plan_clear (TsTileablePlan *plan)
{
  free (plan->band_mask);
  plan->band_mask = NULL;
}

bool
ts_tileable_in_band (const TsTileablePlan *plan, size_t x, size_t y)
{
  if (plan->band_mask)
    return plan->band_mask[y * plan->width + x] != 0;
  return (plan->wrap_x && (x < plan->band_x || x >= plan->width - plan->band_x)) ||
         (plan->wrap_y && (y < plan->band_y || y >= plan->height - plan->band_y));
}

/* Where the parabolas of samples q and p of f meet. */
static double
intersection (const double *f, size_t q, size_t p)
{
  double a = (double) q, b = (double) p;
  return ((f[q] + a * a) - (f[p] + b * b)) / (2.0 * a - 2.0 * b);
}

/* Felzenszwalb & Huttenlocher's 1D squared distance transform of f into d
 * (n samples); v and z are scratch of n and n + 1 entries. */
static void
distance_1d (const double *f, size_t n, double *d, size_t *v, double *z)
{
  size_t k = 0;

  v[0] = 0;
  z[0] = -INFINITY;
  z[1] = INFINITY;
  for (size_t q = 1; q < n; q++)
    {
      double s = intersection (f, q, v[k]);
      /* z[0] is -infinity, so k never goes below 0. */
      while (s <= z[k])
        s = intersection (f, q, v[--k]);
      k++;
      v[k] = q;
      z[k] = s;
      z[k + 1] = INFINITY;
    }
  k = 0;
  for (size_t q = 0; q < n; q++)
    {
      while (z[k + 1] < (double) q)
        k++;
      double t = (double) q - (double) v[k];
      d[q] = t * t + f[v[k]];
    }
}

/* Squared distance transform along one line of n samples read and written
 * with `stride`, wrapping by running over three periods. */
static void
distance_line (double *line, size_t n, size_t stride, bool wrap, double *f, double *d,
               size_t *v, double *z)
{
  size_t copies = wrap ? 3 : 1, m = n * copies;

  for (size_t i = 0; i < m; i++)
    f[i] = line[(i % n) * stride];
  distance_1d (f, m, d, v, z);
  for (size_t i = 0; i < n; i++)
    line[i * stride] = d[(copies / 2) * n + i];
}

TsStatus
ts_tileable_distance (const unsigned char *mask, size_t width, size_t height, bool wrap_x,
                      bool wrap_y, float *distance)
{
  size_t n = width * height, longest = 3 * (width > height ? width : height);
  double *grid = malloc (n * sizeof (double));
  double *f = malloc (longest * sizeof (double)), *d = malloc (longest * sizeof (double));
  double *z = malloc ((longest + 1) * sizeof (double));
  size_t *v = malloc (longest * sizeof (size_t));
  TsStatus status = TS_OK;

  if (!grid || !f || !d || !z || !v)
    status = TS_ERROR_OUT_OF_MEMORY;
  else
    {
      for (size_t i = 0; i < n; i++)
        grid[i] = mask[i] ? 0.0 : TS_TILEABLE_FAR;
      for (size_t y = 0; y < height; y++)
        distance_line (grid + y * width, width, 1, wrap_x, f, d, v, z);
      for (size_t x = 0; x < width; x++)
        distance_line (grid + x, height, width, wrap_y, f, d, v, z);
      for (size_t i = 0; i < n; i++)
        distance[i] = grid[i] >= TS_TILEABLE_FAR ? (float) TS_TILEABLE_FAR : (float) sqrt (grid[i]);
    }
  free (grid);
  free (f);
  free (d);
  free (z);
  free (v);
  return status;
}

/* Source (x, y) of output pixel (x, y) at the start. */
static void
start_source (const TsTileablePlan *plan, size_t x, size_t y, size_t *sx, size_t *sy)
{
  if (ts_tileable_in_band (plan, x, y))
    {
      *sx = (x + plan->shift_x) % plan->width;
      *sy = (y + plan->shift_y) % plan->height;
    }
  else
    {
      *sx = x;
      *sy = y;
    }
}

/* Marks both pixels of every 4-neighbour pair whose sources do not
 * continue each other (a cut in the start map). */
static void
mark_cuts (const TsTileablePlan *plan, const int32_t *source, unsigned char *cut)
{
  size_t w = plan->width, h = plan->height;

  memset (cut, 0, w * h);
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t p = y * w + x;
        if (x + 1 < w || plan->wrap_x)
          {
            size_t q = y * w + (x + 1) % w;
            if (source[2 * q] != source[2 * p] + 1 || source[2 * q + 1] != source[2 * p + 1])
              cut[p] = cut[q] = 1;
          }
        if (y + 1 < h || plan->wrap_y)
          {
            size_t q = ((y + 1) % h) * w + x;
            if (source[2 * q] != source[2 * p] || source[2 * q + 1] != source[2 * p + 1] + 1)
              cut[p] = cut[q] = 1;
          }
      }
}

TsStatus
ts_tileable_maps (const TsTileablePlan *plan, int32_t *source, float *preserve)
{
  size_t w = plan->width, h = plan->height, n = w * h;
  unsigned char *cut = calloc (n, 1);
  TsStatus status;

  if (!cut)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t sx, sy;
        start_source (plan, x, y, &sx, &sy);
        source[2 * (y * w + x)] = (int32_t) sx;
        source[2 * (y * w + x) + 1] = (int32_t) sy;
      }
  mark_cuts (plan, source, cut);
  status = ts_tileable_distance (cut, w, h, plan->wrap_x, plan->wrap_y, preserve);
  if (status == TS_OK)
    for (size_t i = 0; i < n; i++)
      {
        /* Smooth rise: the optimization fades from free to bound. */
        double t = fmin (1.0, (double) preserve[i] / plan->transition);
        preserve[i] = (float) (t * t * (3.0 - 2.0 * t));
      }
  free (cut);
  return status;
}

TsStatus
ts_make_tileable (const TsTileableParams *params, const TsImage *input, TsImage *output,
                  TsProgressFunc progress, void *user_data, TsError *error)
{
  TsParams synthesis;
  TsTileablePlan plan;
  TsImage working = { 0, 0, NULL };
  int32_t *source = NULL;
  float *preserve = NULL;
  size_t n;
  bool engine_said = false;
  TsStatus status = ts_tileable_params_validate (params, input, error);

  if (status != TS_OK)
    return status;
  if (!output || !output->pixels || output->width != input->width ||
      output->height != input->height)
    return ts_fail (error, TS_ERROR_INVALID_ARGUMENT,
                    "the output image must be allocated with the input's size, %zux%zu",
                    input->width, input->height);

  n = input->width * input->height;
  ts_tileable_plan_init (params, input, &plan);
  source = malloc (2 * n * sizeof (int32_t));
  preserve = malloc (n * sizeof (float));
  status = source && preserve ? ts_image_to_working (input, &working) : TS_ERROR_OUT_OF_MEMORY;
  if (status == TS_OK)
    status = ts_tileable_choose_shift (&working, &plan);
  if (status == TS_OK)
    status = ts_tileable_place_cuts (&working, &plan);
  ts_image_free (&working);
  if (status == TS_OK)
    status = ts_tileable_maps (&plan, source, preserve);
  if (status == TS_OK)
    {
      fill_synthesis_params (params, input, &synthesis);
      synthesis.initial_source = source;
      synthesis.preserve = preserve;
      status = ts_synthesize (&synthesis, input, output, progress, user_data, error);
      engine_said = status != TS_OK;   /* `error` already says why */
    }
  free (source);
  free (preserve);
  ts_tileable_plan_clear (&plan);
  if (status != TS_OK && !engine_said)
    return ts_fail (error, status, "%s", ts_status_string (status));
  return status;
}
