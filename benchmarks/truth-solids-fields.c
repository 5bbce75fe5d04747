/* Truth solids drawn from periodic Gaussian random fields: sums of plane
 * waves whose wave vectors are whole numbers of periods across the cube
 * (so the field wraps around exactly) and point every way (so it has no
 * preferred direction). Thresholds split a field into phases; the
 * field's value over its gradient gives the distance to a phase edge,
 * over which the colours blend, so edges are smooth in any slice.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "truth-solids-internal.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
/* Plane waves per field: enough for a near-Gaussian, isotropic field. */
#define WAVES 96

typedef struct
{
  int    m[WAVES][3]; /* wave vector, in periods across the cube */
  double amplitude[WAVES], phase[WAVES];
  double sigma;       /* the field's standard deviation */
} Field;

/* WAVES plane waves in random directions, of wavelengths drawn between
 * `wavelength_lo` and `wavelength_hi` voxels (rounded to whole periods
 * across the cube), amplitude ~ (periods across the cube)^-decay. */
static void
field_init (Field *f, const TruthSolid *s, uint32_t stream, double wavelength_lo, double wavelength_hi,
            double decay)
{
  double variance = 0.0;
  for (int w = 0; w < WAVES; w++)
    {
      uint64_t key = (uint64_t) w * 8u;
      double z = 2.0 * truth_uniform (s, stream, key) - 1.0, phi = 2.0 * PI * truth_uniform (s, stream, key + 1);
      double r = sqrt (fmax (0.0, 1.0 - z * z)), dir[3] = { r * cos (phi), r * sin (phi), z };
      double wavelength = wavelength_lo + (wavelength_hi - wavelength_lo) * truth_uniform (s, stream, key + 2);
      double periods = (double) s->n / wavelength, length = 0.0;
      for (int a = 0; a < 3; a++)
        {
          f->m[w][a] = (int) lround (periods * dir[a]);
          length += (double) f->m[w][a] * f->m[w][a];
        }
      if (length == 0.0)
        {
          f->m[w][2] = 1;
          length = 1.0;
        }
      f->amplitude[w] = pow (sqrt (length), -decay);
      f->phase[w] = 2.0 * PI * truth_uniform (s, stream, key + 3);
      variance += 0.5 * f->amplitude[w] * f->amplitude[w];
    }
  f->sigma = sqrt (variance);
}

/* The field in units of its standard deviation at every voxel, and the
 * length of its gradient per voxel; false if out of memory. */
static bool
field_sample (const Field *f, size_t n, float *value, float *slope)
{
  double complex *along = malloc (3 * WAVES * n * sizeof (double complex));
  double complex row[WAVES];
  if (!along)
    return false;
  /* e^(2 pi i m x / n) per wave, axis and coordinate */
  for (int w = 0; w < WAVES; w++)
    for (int a = 0; a < 3; a++)
      for (size_t x = 0; x < n; x++)
        along[((size_t) w * 3 + (size_t) a) * n + x]
          = cexp (I * 2.0 * PI * (double) f->m[w][a] * (double) x / (double) n);
  for (size_t z = 0; z < n; z++)
    for (size_t y = 0; y < n; y++)
      {
        for (int w = 0; w < WAVES; w++)
          row[w] = f->amplitude[w] * cexp (I * f->phase[w]) * along[((size_t) w * 3 + 1) * n + y]
                   * along[((size_t) w * 3 + 2) * n + z];
        for (size_t x = 0; x < n; x++)
          {
            double v = 0.0, g[3] = { 0.0, 0.0, 0.0 };
            for (int w = 0; w < WAVES; w++)
              {
                double complex e = row[w] * along[(size_t) w * 3 * n + x];
                double k = 2.0 * PI / (double) n;
                v += creal (e);
                for (int a = 0; a < 3; a++)
                  g[a] -= k * f->m[w][a] * cimag (e);
              }
            value[(z * n + y) * n + x] = (float) (v / f->sigma);
            slope[(z * n + y) * n + x] = (float) (sqrt (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) / f->sigma);
          }
      }
  free (along);
  return true;
}

/* How much of a voxel lies above `threshold`, from its distance to the
 * level set (value over gradient), blended over one voxel. */
static double
above (float value, float slope, double threshold)
{
  double d = ((double) value - threshold) / fmax ((double) slope, 1e-6);
  return fmin (1.0, fmax (0.0, 0.5 + d));
}

static void
mix (double out[3], const double a[3], const double b[3], double t)
{
  for (int c = 0; c < 3; c++)
    out[c] = a[c] + t * (b[c] - a[c]);
}

/* Thresholds below which 35 % and a third of a Gaussian field lie (in
 * standard deviations): the sponge's pores, threephase's dark phase. */
#define QUANTILE_35 (-0.3853)
#define QUANTILE_33 (-0.4307)

typedef struct
{
  float *value[2], *slope[2];
} Fields;

static void
paint (const char *kind, const TruthSolid *s, const Fields *f, uint8_t *rgb)
{
  size_t n = s->n, fine = truth_lattice_period (s, 2.0), broad = truth_lattice_period (s, 24.0);
  for (size_t z = 0; z < n; z++)
    for (size_t y = 0; y < n; y++)
      for (size_t x = 0; x < n; x++)
        {
          size_t v = (z * n + y) * n + x;
          double p[3] = { (double) x, (double) y, (double) z }, colour[3], noise;
          double grain = truth_value_noise (s, 400, fine, p) - 0.5;
          double wide = truth_value_noise (s, 401, broad, p) - 0.5;
          float v0 = f->value[0][v], s0 = f->slope[0][v];
          if (!strcmp (kind, "sponge"))
            {
              /* pores where the field is lowest, in a tan solid */
              static const double pore[3] = { 50, 38, 32 }, solid[3] = { 200, 172, 135 };
              mix (colour, pore, solid, above (v0, s0, QUANTILE_35));
              noise = 20.0 * grain + 30.0 * wide;
            }
          else if (!strcmp (kind, "twophase"))
            {
              static const double green[3] = { 118, 134, 108 }, rust[3] = { 168, 96, 62 };
              mix (colour, green, rust, above (v0, s0, 0.0));
              noise = 22.0 * grain + 16.0 * wide;
            }
          else if (!strcmp (kind, "threephase"))
            {
              /* a dark phase where the first field is lowest, the rest
               * split by the second field's sign */
              static const double dark[3] = { 45, 45, 56 }, cream[3] = { 222, 206, 170 },
                                  teal[3] = { 70, 122, 140 };
              double rest[3];
              mix (rest, teal, cream, above (f->value[1][v], f->slope[1][v], 0.0));
              mix (colour, dark, rest, above (v0, s0, QUANTILE_33));
              noise = 22.0 * grain;
            }
          else
            {
              /* marble: continuous tones, grey-green veins where the
               * field crosses zero, on a cream whose shade drifts */
              static const double base[3] = { 232, 226, 212 }, vein[3] = { 92, 104, 96 };
              double t = (double) v0 / 0.35, drift = (double) f->value[1][v];
              mix (colour, base, vein, 0.85 * exp (-t * t));
              for (int c = 0; c < 3; c++)
                colour[c] -= 10.0 * drift + (c == 2 ? 6.0 * drift : 0.0);
              noise = 6.0 * grain;
            }
          for (int c = 0; c < 3; c++)
            rgb[3 * v + (size_t) c] = truth_byte (colour[c] + noise);
        }
}

TruthStatus
truth_render_fields (const char *kind, const TruthSolid *s, uint8_t *rgb)
{
  /* feature sizes in voxels (shortest and longest wavelength), spectral decay */
  static const struct
  {
    const char *name;
    int fields;
    double lo[2], hi[2], decay[2];
  } kinds[] = {
    { "sponge", 1, { 12, 0 }, { 14, 0 }, { 0, 0 } },
    { "twophase", 1, { 10, 0 }, { 28, 0 }, { 1, 0 } },
    { "threephase", 2, { 14, 9 }, { 18, 12 }, { 0, 0 } },
    { "marble", 2, { 12, 20 }, { 60, 60 }, { 1.5, 1 } },
  };
  size_t voxels = s->n * s->n * s->n;
  Fields f = { { NULL, NULL }, { NULL, NULL } };
  TruthStatus status = TRUTH_OUT_OF_MEMORY;
  int which = -1;

  for (int k = 0; k < (int) (sizeof kinds / sizeof kinds[0]); k++)
    if (!strcmp (kind, kinds[k].name))
      which = k;
  if (which < 0)
    return TRUTH_UNKNOWN;
  for (int i = 0; i < 2; i++)
    {
      f.value[i] = malloc (voxels * sizeof (float));
      f.slope[i] = malloc (voxels * sizeof (float));
    }
  if (f.value[0] && f.value[1] && f.slope[0] && f.slope[1])
    {
      bool ok = true;
      for (int i = 0; ok && i < kinds[which].fields; i++)
        {
          Field field;
          field_init (&field, s, 500 + 10 * (uint32_t) which + (uint32_t) i, kinds[which].lo[i],
                      kinds[which].hi[i], kinds[which].decay[i]);
          ok = field_sample (&field, s->n, f.value[i], f.slope[i]);
        }
      if (ok)
        {
          paint (kind, s, &f, rgb);
          status = TRUTH_DONE;
        }
    }
  for (int i = 0; i < 2; i++)
    {
      free (f.value[i]);
      free (f.slope[i]);
    }
  return status;
}
