/* Makes test images for the texsynth-measure tests from an exemplar:
 * tilings, crops, rolls, block collages, blur and noise. Several commands,
 * joined by '+', run in turn in one process (one GEGL start-up for all),
 * so a later one can read an earlier one's output.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "image-io.h"
#include "engine/rng.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage_text[] =
  "usage: measure-fixture tile IN OUT NX NY\n"
  "       measure-fixture crop IN OUT X Y W H\n"
  "       measure-fixture roll IN OUT DX DY      (wrap-around shift)\n"
  "       measure-fixture blocks IN OUT W H BLOCK SEED [OFFSET]\n"
  "                                              (collage of random exemplar blocks)\n"
  "       measure-fixture blur IN OUT SIGMA      (Gaussian, in Lab)\n"
  "       measure-fixture noise OUT W H SEED     (uniform random colours)\n"
  "       measure-fixture COMMAND... + COMMAND...  (in turn, stopping at a failure)\n";

static bool
alloc_image (TsImage *im, size_t w, size_t h)
{
  im->width = w;
  im->height = h;
  im->pixels = calloc (w * h * TS_CHANNELS, sizeof (float));
  return im->pixels != NULL;
}

static float *
px (const TsImage *im, size_t x, size_t y)
{
  return im->pixels + (y * im->width + x) * TS_CHANNELS;
}

static size_t
arg_size (const char *s)
{
  char *end;
  long v = strtol (s, &end, 10);
  if (*end != '\0' || v < 0)
    {
      fprintf (stderr, "measure-fixture: bad number '%s'\n", s);
      exit (2);
    }
  return (size_t) v;
}

static size_t
wrap (ptrdiff_t i, size_t n)
{
  ptrdiff_t m = i % (ptrdiff_t) n;
  return (size_t) (m < 0 ? m + (ptrdiff_t) n : m);
}

/* Separable Gaussian of L, a, b with clamped edges. */
static bool
blur (const TsImage *in, TsImage *out, double sigma)
{
  int r = (int) ceil (3.0 * sigma);
  size_t w = in->width, h = in->height;
  double *k = malloc ((size_t) (2 * r + 1) * sizeof (double)), ksum = 0.0;
  TsImage tmp;
  if (!k || !alloc_image (&tmp, w, h) || !alloc_image (out, w, h))
    return false;
  for (int i = -r; i <= r; i++)
    ksum += k[i + r] = exp (-0.5 * i * i / (sigma * sigma));
  for (int pass = 0; pass < 2; pass++)
    {
      const TsImage *src = pass == 0 ? in : &tmp;
      TsImage *dst = pass == 0 ? &tmp : out;
      for (size_t y = 0; y < h; y++)
        for (size_t x = 0; x < w; x++)
          {
            double acc[3] = { 0, 0, 0 };
            for (int i = -r; i <= r; i++)
              {
                ptrdiff_t sx = (ptrdiff_t) x + (pass == 0 ? i : 0);
                ptrdiff_t sy = (ptrdiff_t) y + (pass == 1 ? i : 0);
                sx = sx < 0 ? 0 : sx >= (ptrdiff_t) w ? (ptrdiff_t) w - 1 : sx;
                sy = sy < 0 ? 0 : sy >= (ptrdiff_t) h ? (ptrdiff_t) h - 1 : sy;
                for (int c = 0; c < 3; c++)
                  acc[c] += k[i + r] * px (src, (size_t) sx, (size_t) sy)[c];
              }
            for (int c = 0; c < 3; c++)
              px (dst, x, y)[c] = (float) (acc[c] / ksum);
            px (dst, x, y)[3] = 1.0f;
          }
    }
  free (k);
  free (tmp.pixels);
  return true;
}

/* One command: argv[0] is its name, argv[1..argc-1] its arguments. */
static int
make (int argc, char **argv)
{
  TsImage in = { 0 }, out = { 0 };
  const char *cmd, *out_path;
  char why[512];
  int first_out = 3;

  /* Shifted one back, so argv[i] is the i-th argument as in main's. */
  argc++;
  argv--;
  cmd = argc > 1 ? argv[1] : "";

  if ((strcmp (cmd, "tile") == 0 && argc == 6) || (strcmp (cmd, "roll") == 0 && argc == 6)
      || (strcmp (cmd, "crop") == 0 && argc == 8) || (strcmp (cmd, "blocks") == 0 && (argc == 8 || argc == 9))
      || (strcmp (cmd, "blur") == 0 && argc == 5))
    {
      if (!ts_io_load (argv[2], &in, why, sizeof why))
        {
          fprintf (stderr, "measure-fixture: %s\n", why);
          return 2;
        }
    }
  else if (strcmp (cmd, "noise") == 0 && argc == 6)
    first_out = 2;
  else
    {
      fputs (usage_text, stderr);
      return 2;
    }
  out_path = argv[first_out];

  if (strcmp (cmd, "tile") == 0 || strcmp (cmd, "roll") == 0)
    {
      bool tile = cmd[0] == 't';
      size_t a = arg_size (argv[4]), b = arg_size (argv[5]);
      size_t w = tile ? in.width * a : in.width, h = tile ? in.height * b : in.height;
      if (!alloc_image (&out, w, h))
        return 2;
      for (size_t y = 0; y < h; y++)
        for (size_t x = 0; x < w; x++)
          memcpy (px (&out, x, y),
                  px (&in, tile ? x % in.width : wrap ((ptrdiff_t) x - (ptrdiff_t) a, w),
                      tile ? y % in.height : wrap ((ptrdiff_t) y - (ptrdiff_t) b, h)),
                  TS_CHANNELS * sizeof (float));
    }
  else if (strcmp (cmd, "crop") == 0)
    {
      size_t x0 = arg_size (argv[4]), y0 = arg_size (argv[5]);
      size_t w = arg_size (argv[6]), h = arg_size (argv[7]);
      if (x0 + w > in.width || y0 + h > in.height || !alloc_image (&out, w, h))
        return 2;
      for (size_t y = 0; y < h; y++)
        memcpy (px (&out, 0, y), px (&in, x0, y0 + y), w * TS_CHANNELS * sizeof (float));
    }
  else if (strcmp (cmd, "blocks") == 0)
    {
      /* Blocks on a grid shifted by OFFSET and wrapped around the edges:
       * with OFFSET > 0 and sizes that are multiples of BLOCK, blocks
       * straddle the edges intact, so the collage tiles like its inside. */
      size_t w = arg_size (argv[4]), h = arg_size (argv[5]), bs = arg_size (argv[6]);
      uint32_t seed = (uint32_t) arg_size (argv[7]);
      ptrdiff_t off = argc > 8 ? (ptrdiff_t) arg_size (argv[8]) : 0;
      if (bs == 0 || bs > in.width || bs > in.height || !alloc_image (&out, w, h))
        return 2;
      for (ptrdiff_t by = -off; by < (ptrdiff_t) h - off; by += (ptrdiff_t) bs)
        for (ptrdiff_t bx = -off; bx < (ptrdiff_t) w - off; bx += (ptrdiff_t) bs)
          {
            size_t sx = ts_lcg_next24 (&seed) % (in.width - bs + 1);
            size_t sy = ts_lcg_next24 (&seed) % (in.height - bs + 1);
            for (size_t y = 0; y < bs; y++)
              for (size_t x = 0; x < bs; x++)
                memcpy (px (&out, wrap (bx + (ptrdiff_t) x, w), wrap (by + (ptrdiff_t) y, h)),
                        px (&in, sx + x, sy + y), TS_CHANNELS * sizeof (float));
          }
    }
  else if (strcmp (cmd, "blur") == 0)
    {
      if (!blur (&in, &out, atof (argv[4])))
        return 2;
    }
  else
    {
      size_t w = arg_size (argv[3]), h = arg_size (argv[4]);
      uint32_t seed = (uint32_t) arg_size (argv[5]);
      if (!alloc_image (&out, w, h))
        return 2;
      for (size_t i = 0; i < w * h; i++)
        {
          float *p = out.pixels + i * TS_CHANNELS;
          p[0] = (float) (ts_lcg_next24 (&seed) % 1001) / 10.0f;
          p[1] = (float) (ts_lcg_next24 (&seed) % 161) - 80.0f;
          p[2] = (float) (ts_lcg_next24 (&seed) % 161) - 80.0f;
          p[3] = 1.0f;
        }
    }

  if (!ts_io_save (out_path, &out, why, sizeof why))
    {
      fprintf (stderr, "measure-fixture: %s\n", why);
      return 2;
    }
  free (in.pixels);
  free (out.pixels);
  return 0;
}

int
main (int argc, char **argv)
{
  int start = 1, code = 0;

  ts_io_init ();
  for (int i = 1; i <= argc && code == 0; i++)
    if (i == argc || strcmp (argv[i], "+") == 0)
      {
        code = make (i - start, argv + start);
        start = i + 1;
      }
  return code;
}
