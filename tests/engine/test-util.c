#include "test-util.h"
#include "image-io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

int ts_test_failures = 0;

int
test_finish (const char *name)
{
  if (ts_test_failures)
    fprintf (stderr, "%s: %d check(s) failed\n", name, ts_test_failures);
  else
    printf ("%s: all checks passed\n", name);
  return ts_test_failures ? 1 : 0;
}

bool
test_small (void)
{
  const char *value = getenv ("TEXSYNTH_TEST_SMALL");

  return value && *value && strcmp (value, "0") != 0;
}

void
test_load_exemplar (const char *name, TsImage *image)
{
  const char *dir = getenv ("TEXSYNTH_EXEMPLARS");
  char path[4096], why[512];

  if (!dir)
    {
      fprintf (stderr, "TEXSYNTH_EXEMPLARS is not set\n");
      exit (1);
    }
  snprintf (path, sizeof path, "%s/%s", dir, name);
  ts_io_init ();
  if (!ts_io_load (path, image, why, sizeof why))
    {
      fprintf (stderr, "cannot load exemplar: %s\n", why);
      exit (1);
    }
}

static float
hash_unit (unsigned seed, long x, long y)
{
  unsigned long h = (unsigned long) seed * 2654435761UL ^ (unsigned long) x * 40503UL ^ (unsigned long) y * 9973UL;
  h ^= h >> 13;
  h *= 0x5bd1e995UL;
  h ^= h >> 15;
  return (float) (h & 0xffff) / 65535.0f;
}

void
test_synthesize (const char *name, const TsImage *exemplar, TsImage *out, uint32_t seed,
                 bool tileable)
{
  TsParams params;
  TsError error = { TS_OK, "" };

  ts_params_init (&params);
  params.output_width = out->width;
  params.output_height = out->height;
  params.seed = seed;
  params.wrap_x = params.wrap_y = tileable;
  CHECK (ts_synthesize (&params, exemplar, out, NULL, NULL, &error) == TS_OK, "%s seed %u: %s",
         name, seed, error.message);
}

void
test_noise_image (TsImage *image, size_t width, size_t height, unsigned seed)
{
  image->width = width;
  image->height = height;
  image->pixels = calloc (width * height * TS_CHANNELS, sizeof (float));
  if (!image->pixels)
    {
      fprintf (stderr, "out of memory\n");
      exit (1);
    }
  for (size_t y = 0; y < height; y++)
    for (size_t x = 0; x < width; x++)
      {
        float *p = image->pixels + (y * width + x) * TS_CHANNELS;
        /* Two octaves of value noise on a 4 px and 8 px lattice. */
        float v = 0;
        for (int octave = 0; octave < 2; octave++)
          {
            long cell = 4L << octave;
            long cx = (long) x / cell, cy = (long) y / cell;
            float fx = (float) ((long) x % cell) / (float) cell, fy = (float) ((long) y % cell) / (float) cell;
            float a = hash_unit (seed + (unsigned) octave, cx, cy), b = hash_unit (seed + (unsigned) octave, cx + 1, cy);
            float c = hash_unit (seed + (unsigned) octave, cx, cy + 1), d = hash_unit (seed + (unsigned) octave, cx + 1, cy + 1);
            v += ((a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy) / (float) (octave + 1);
          }
        p[0] = 20.0f + 40.0f * v;
        p[1] = 30.0f * sinf ((float) x * 0.3f) * v;
        p[2] = 10.0f * cosf ((float) y * 0.2f);
        p[3] = 1.0f;
      }
}

long
test_peak_rss_kib (void)
{
  /* VmHWM belongs to this program's address space; getrusage's maxrss
   * also keeps the peak of the process before exec (meson's runner). */
  FILE *f = fopen ("/proc/self/status", "r");
  char line[256];
  long kib = -1;
  struct rusage usage;

  while (f && kib < 0 && fgets (line, sizeof line, f))
    if (sscanf (line, "VmHWM: %ld kB", &kib) != 1)
      kib = -1;
  if (f)
    fclose (f);
  if (kib >= 0)
    return kib;
  getrusage (RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}
