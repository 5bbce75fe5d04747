/* Phase thickness and specks of a solid's slices (phase-thickness.h).
 *
 * Why the thickness: the blobs' slices lose edge (sharpness) because
 * neighbouring spots merge into thicker bodies than any the exemplar
 * shows, not because their edges soften; the mean gradient sees the
 * loss, this figure sees its cause.
 *
 * Why the specks: the cells' ragged mortar is a band of lone voxels of
 * either phase. Sharpness counts their edges as edge, so a speckled
 * slice scores as sharp as a clean one; this figure tells them apart.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "phase-thickness.h"
#include "slice-figures.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static int
compare_float (const void *a, const void *b)
{
  float x = *(const float *) a, y = *(const float *) b;
  return (x > y) - (x < y);
}

/* The lightness splitting the phases and which side is the minority. */
static bool
split (const TsImage *ex, float *threshold, bool *below)
{
  size_t count = ex->width * ex->height, under = 0;
  float *light = malloc (count * sizeof (float));

  if (!light)
    return false;
  for (size_t i = 0; i < count; i++)
    light[i] = ex->pixels[i * TS_CHANNELS];
  qsort (light, count, sizeof (float), compare_float);
  *threshold = 0.5f * (light[count / 20] + light[count - 1 - count / 20]);
  for (size_t i = 0; i < count; i++)
    under += light[i] < *threshold;
  *below = 2 * under < count;
  free (light);
  return true;
}

/* One erosion by the cross; `wrap` joins opposite edges, otherwise a
 * pixel outside counts as in the phase (only inner pixels are counted). */
static void
erode (const uint8_t *in, uint8_t *out, size_t w, size_t h, bool wrap)
{
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t l = x > 0 ? x - 1 : (wrap ? w - 1 : x), r = x + 1 < w ? x + 1 : (wrap ? 0 : x);
        size_t u = y > 0 ? y - 1 : (wrap ? h - 1 : y), d = y + 1 < h ? y + 1 : (wrap ? 0 : y);
        out[y * w + x] = in[y * w + x] && in[y * w + l] && in[y * w + r] && in[u * w + x]
                         && in[d * w + x];
      }
}

/* Adds the image's phase pixels and those surviving the erosions, over
 * the pixels at least PHASE_EROSIONS from the edge unless `wrap`. */
static void
count_image (const TsImage *img, float threshold, bool below, bool wrap, uint8_t *mask,
             uint8_t *scratch, double *phase, double *survivors)
{
  size_t w = img->width, h = img->height, m = wrap ? 0 : PHASE_EROSIONS;

  for (size_t i = 0; i < w * h; i++)
    {
      float light = img->pixels[i * TS_CHANNELS];
      mask[i] = below ? light < threshold : light > threshold;
    }
  for (size_t y = m; y + m < h; y++)
    for (size_t x = m; x + m < w; x++)
      *phase += mask[y * w + x];
  for (int k = 0; k < PHASE_EROSIONS; k++)
    {
      erode (mask, scratch, w, h, wrap);
      memcpy (mask, scratch, w * h);
    }
  for (size_t y = m; y + m < h; y++)
    for (size_t x = m; x + m < w; x++)
      *survivors += mask[y * w + x];
}

bool
phase_thickness (const TsImage *exemplar, const float *volume, size_t n, double *ratio)
{
  size_t side = n > exemplar->width ? n : exemplar->width;
  size_t area = side * (n > exemplar->height ? n : exemplar->height);
  TsImage slice = { n, n, malloc (n * n * TS_CHANNELS * sizeof (float)) };
  uint8_t *mask = malloc (area), *scratch = malloc (area);
  double ex_phase = 0.0, ex_survivors = 0.0, phase = 0.0, survivors = 0.0;
  float threshold;
  bool below, ok = slice.pixels && mask && scratch && split (exemplar, &threshold, &below);

  if (ok)
    {
      count_image (exemplar, threshold, below, false, mask, scratch, &ex_phase, &ex_survivors);
      for (int axis = 0; axis < 3; axis++)
        for (size_t k = 0; k < n; k++)
          {
            slice_cut (volume, n, axis, k, &slice);
            count_image (&slice, threshold, below, true, mask, scratch, &phase, &survivors);
          }
      *ratio = ex_survivors > 0.0 && phase > 0.0
               ? (survivors / phase) / (ex_survivors / ex_phase) : NAN;
    }
  free (slice.pixels);
  free (mask);
  free (scratch);
  return ok;
}

/* Lightness spread of light sections: squared deviations from their
 * own section's mean, the pixels they sum over, and for the spread of
 * the sections' means their lightness sum and sum of sum^2 / size. */
typedef struct
{
  double squares;
  size_t pixels;
  double sum, mean_squares;
  double step[2];  /* |lightness step| summed over 4-neighbour pairs */
  size_t pairs[2]; /* within the light [0] and the dark [1] phase   */
} Tones;

/* Adds one wrapped slice's lightness steps between 4-neighbours of the
 * same phase. */
static void
count_steps (const uint8_t *mask, const float *pixels, size_t w, size_t h, Tones *tones)
{
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        size_t i = y * w + x, next[2] = { y * w + (x + 1) % w, ((y + 1) % h) * w + x };
        for (int k = 0; k < 2; k++)
          if (mask[next[k]] == mask[i])
            {
              tones->step[mask[i]] += fabs ((double) pixels[i * TS_CHANNELS]
                                            - pixels[next[k] * TS_CHANNELS]);
              tones->pairs[mask[i]]++;
            }
      }
}

/* Specks of one wrapped slice's phase mask, and in *sections its pieces
 * of the light phase (mask 0) larger than a speck; `stack` holds w * h
 * indices and `seen` w * h flags. */
static size_t
count_specks (const uint8_t *mask, const float *pixels, size_t w, size_t h, uint8_t *seen,
              size_t *stack, size_t *sections, Tones *tones)
{
  size_t specks = 0;

  memset (seen, 0, w * h);
  for (size_t start = 0; start < w * h; start++)
    {
      size_t top = 0, size = 0;
      double sum = 0.0, square = 0.0;
      if (seen[start])
        continue;
      seen[start] = 1;
      stack[top++] = start;
      while (top > 0)
        {
          size_t i = stack[--top], x = i % w, y = i / w;
          size_t next[4] = { y * w + (x + w - 1) % w, y * w + (x + 1) % w,
                             ((y + h - 1) % h) * w + x, ((y + 1) % h) * w + x };
          size++;
          sum += pixels[i * TS_CHANNELS];
          square += (double) pixels[i * TS_CHANNELS] * pixels[i * TS_CHANNELS];
          for (int k = 0; k < 4; k++)
            if (!seen[next[k]] && mask[next[k]] == mask[start])
              {
                seen[next[k]] = 1;
                stack[top++] = next[k];
              }
        }
      specks += size <= PHASE_SPECK_PIXELS;
      *sections += size > PHASE_SPECK_PIXELS && !mask[start];
      if (size > PHASE_SPECK_PIXELS && !mask[start])
        {
          tones->squares += fmax (square - sum * sum / (double) size, 0.0);
          tones->pixels += size;
          tones->sum += sum;
          tones->mean_squares += sum * sum / (double) size;
        }
    }
  return specks;
}

/* Specks and light sections of every x, y and z slice of `volume`, or
 * with volume NULL of the exemplar (n x n) alone. */
static bool
count_phases (const TsImage *exemplar, const float *volume, size_t n, size_t *specks,
              size_t *sections, Tones *tones)
{
  TsImage slice = { n, n, malloc (n * n * TS_CHANNELS * sizeof (float)) };
  uint8_t *mask = malloc (n * n), *seen = malloc (n * n);
  size_t *stack = malloc (n * n * sizeof (size_t));
  float threshold;
  bool below, ok = slice.pixels && mask && seen && stack && split (exemplar, &threshold, &below);

  *specks = *sections = 0;
  memset (tones, 0, sizeof *tones);
  for (int axis = 0; ok && axis < (volume ? 3 : 1); axis++)
    for (size_t k = 0; k < (volume ? n : 1); k++)
      {
        const TsImage *cut = volume ? &slice : exemplar;
        if (volume)
          slice_cut (volume, n, axis, k, &slice);
        for (size_t i = 0; i < n * n; i++)
          mask[i] = cut->pixels[i * TS_CHANNELS] < threshold;
        *specks += count_specks (mask, cut->pixels, n, n, seen, stack, sections, tones);
        count_steps (mask, cut->pixels, n, n, tones);
      }
  free (slice.pixels);
  free (mask);
  free (seen);
  free (stack);
  return ok;
}

/* The pixel-weighted variance of the light sections' mean lightness. */
static double
shade_variance (const Tones *t)
{
  double mean = t->sum / (double) t->pixels;
  return fmax (t->mean_squares / (double) t->pixels - mean * mean, 0.0);
}

bool
phase_figures (const TsImage *exemplar, const float *volume, size_t n, PhaseFigures *figures)
{
  size_t specks, sections, their_specks, their_sections;
  Tones tones, theirs;
  bool square = exemplar->width == n && exemplar->height == n;

  if (!count_phases (exemplar, volume, n, &specks, &sections, &tones)
      || (square && !count_phases (exemplar, NULL, n, &their_specks, &their_sections, &theirs)))
    return false;
  figures->specks = 1000.0 * (double) specks / (3.0 * (double) n * (double) n * (double) n);
  figures->sections = square && their_sections
                        ? (double) sections / (3.0 * (double) n * (double) their_sections)
                        : NAN;
  figures->tones = square && tones.pixels && theirs.pixels && theirs.squares > 0.0
                     ? sqrt (tones.squares / (double) tones.pixels
                             / (theirs.squares / (double) theirs.pixels))
                     : NAN;
  for (int dark = 0; dark < 2; dark++)
    figures->grain[dark] = square && tones.pairs[dark] && theirs.pairs[dark] && theirs.step[dark] > 0.0
                             ? tones.step[dark] / (double) tones.pairs[dark]
                                 / (theirs.step[dark] / (double) theirs.pairs[dark])
                             : NAN;
  figures->shades = NAN;
  if (square && tones.pixels && theirs.pixels)
    {
      double ours = shade_variance (&tones), their = shade_variance (&theirs);
      /* Stones of one tone (blobs) leave only rounding: no spread. */
      figures->shades = their > 0.01 ? sqrt (ours / their) : NAN;
    }
  return true;
}
