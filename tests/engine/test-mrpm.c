/* MRPM candidate sets against brute-force k-NN in the same feature space. */
#include "engine/mrpm.h"
#include "engine/indexing.h"
#include "test-util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

/* Thresholds from measurement with margin. Measured with the defaults:
 * coarsest (brute force in PCA space) recall 0.89-1.0, finer levels
 * 0.51 (bark, fine-detail noise) to 0.75, distance ratio <= 1.09. */
#define MIN_RECALL_COARSEST 0.85
#define MIN_RECALL_FINER 0.45
#define MAX_RATIO 1.15

static double
now (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

/* k per level as the synthesis would use: large at coarse levels. */
static size_t
k_for_level (size_t level)
{
  return level == 0 ? 8 : 24;
}

/* A cancel callback that counts its calls and says stop. */
static bool
say_stop (void *data)
{
  ++*(int *) data;
  return false;
}

static void
build_pyramid (const TsImage *lab, TsPyramid *pyramid)
{
  TsImage work;
  CHECK (ts_image_to_working (lab, &work) == TS_OK, "to_working");
  size_t depth = ts_pyramid_depth_for (lab->width, lab->height, 32);
  CHECK (ts_pyramid_build (&work, depth, pyramid) == TS_OK, "pyramid_build");
  ts_image_free (&work);
}

/* All levels, coarse to fine; sets[l] for level l. Returns seconds. */
static double
run_mrpm (const TsPyramid *pyramid, const TsMrpmOptions *options, TsCandidateSet *sets)
{
  double t0 = now ();
  for (size_t l = pyramid->levels; l-- > 0;)
    {
      const TsCandidateSet *coarser = l + 1 < pyramid->levels ? &sets[l + 1] : NULL;
      TsStatus st = ts_mrpm_level (pyramid, l, coarser, k_for_level (l), options, NULL, &sets[l]);
      CHECK (st == TS_OK, "ts_mrpm_level level %zu: %d", l, (int) st);
    }
  return now () - t0;
}

static void
free_sets (TsCandidateSet *sets, size_t n)
{
  for (size_t l = 0; l < n; l++)
    ts_candidate_set_free (&sets[l]);
}

static int
excluded (size_t a, size_t b, size_t w, size_t radius)
{
  ptrdiff_t dx = (ptrdiff_t) (a % w) - (ptrdiff_t) (b % w);
  ptrdiff_t dy = (ptrdiff_t) (a / w) - (ptrdiff_t) (b / w);
  return labs ((long) dx) <= (long) radius && labs ((long) dy) <= (long) radius;
}

/* Structural checks on every entry of one level's set. */
static void
check_set (const TsPyramid *pyramid, size_t level, const TsCandidateSet *set, const TsMrpmOptions *o)
{
  const TsImage *im = &pyramid->level[level];
  size_t w = im->width, h = im->height, k = set->k, r = ts_mrpm_radius (pyramid, level, o);
  size_t bad = 0;

  CHECK (set->width == w && set->height == h && set->index, "set geometry");
  for (size_t y = 0; y < h && !bad; y++)
    for (size_t x = 0; x < w && !bad; x++)
      {
        size_t p = y * w + x;
        size_t cx = ts_clamp_centre ((ptrdiff_t) x, w, r), cy = ts_clamp_centre ((ptrdiff_t) y, h, r);
        size_t c = cy * w + cx;
        const int32_t *e = set->index + p * k;
        int ended = 0;
        float prev = 0;
        if (c != p && memcmp (e, set->index + c * k, k * sizeof *e) != 0)
          bad++, fprintf (stderr, "level %zu (%zu,%zu): differs from clamped centre\n", level, x, y);
        for (size_t i = 0; i < k && !bad; i++)
          {
            if (e[i] < 0)
              {
                if (e[i] != -1)
                  bad++, fprintf (stderr, "negative entry %d\n", e[i]);
                ended = 1;
                continue;
              }
            size_t q = (size_t) e[i], qx = q % w, qy = q / w;
            if (ended)
              bad++, fprintf (stderr, "entry after -1\n");
            else if (q >= w * h)
              bad++, fprintf (stderr, "entry out of range\n");
            else if (qx < r || qy < r || qx + r >= w || qy + r >= h)
              bad++, fprintf (stderr, "level %zu: candidate (%zu,%zu) patch crosses border\n", level, qx, qy);
            else if (excluded (q, p, w, o->exclude_radius) || excluded (q, c, w, o->exclude_radius))
              bad++, fprintf (stderr, "level %zu (%zu,%zu): near-self candidate (%zu,%zu)\n", level, x, y, qx, qy);
            else if (ts_image_pixel (im, qx, qy)[3] == 0.0f)
              bad++, fprintf (stderr, "level %zu: transparent candidate (%zu,%zu)\n", level, qx, qy);
            for (size_t j = 0; j < i && !bad; j++)
              if (e[j] == e[i])
                bad++, fprintf (stderr, "duplicate entry\n");
            if (!bad)
              {
                float d = ts_mrpm_distance (pyramid, level, o, c, q);
                if (d < prev)
                  bad++, fprintf (stderr, "level %zu: not best first\n", level);
                prev = d;
              }
          }
      }
  CHECK (bad == 0, "level %zu: invalid candidate set", level);
}

/* Brute force over every valid centre for about `queries` valid centres;
 * prints and returns recall and the mean i-th distance ratio. */
static void
compare_brute (const TsPyramid *pyramid, size_t level, const TsCandidateSet *set,
               const TsMrpmOptions *o, size_t queries, double *recall, double *ratio)
{
  const TsImage *im = &pyramid->level[level];
  size_t w = im->width, h = im->height, k = set->k, r = ts_mrpm_radius (pyramid, level, o);
  size_t valid = (w - 2 * r) * (h - 2 * r), step = valid / queries ? valid / queries : 1;
  float *td = malloc (k * sizeof (float));
  size_t *ti = malloc (k * sizeof (size_t));
  size_t found = 0, wanted = 0, nratio = 0, vi = 0;
  double rsum = 0;

  CHECK (td && ti, "out of memory");
  for (size_t y = r; y + r < h; y++)
    for (size_t x = r; x + r < w; x++, vi++)
      {
        size_t p = y * w + x, n = 0;
        if (vi % step)
          continue;
        for (size_t qy = r; qy + r < h; qy++)
          for (size_t qx = r; qx + r < w; qx++)
            {
              size_t q = qy * w + qx;
              if (excluded (q, p, w, o->exclude_radius) || ts_image_pixel (im, qx, qy)[3] == 0.0f)
                continue;
              float d = ts_mrpm_distance (pyramid, level, o, p, q);
              if (n == k && d >= td[k - 1])
                continue;
              size_t pos = n < k ? n++ : k - 1;
              while (pos > 0 && td[pos - 1] > d)
                td[pos] = td[pos - 1], ti[pos] = ti[pos - 1], pos--;
              td[pos] = d, ti[pos] = q;
            }
        const int32_t *e = set->index + p * k;
        wanted += n;
        for (size_t i = 0; i < n; i++)
          {
            for (size_t j = 0; j < k; j++)
              if (e[j] >= 0 && (size_t) e[j] == ti[i])
                {
                  found++;
                  break;
                }
            /* Count a missing entry as a failure of the ratio too. */
            float dm = e[i] >= 0 ? ts_mrpm_distance (pyramid, level, o, p, (size_t) e[i]) : 10 * td[i] + 1;
            rsum += ((double) dm + 1e-3) / ((double) td[i] + 1e-3);
            nratio++;
          }
      }
  *recall = wanted ? (double) found / (double) wanted : 1.0;
  *ratio = nratio ? rsum / (double) nratio : 1.0;
  free (td);
  free (ti);
}

static void
test_exemplar (const char *label, const TsImage *lab)
{
  TsMrpmOptions o;
  TsPyramid pyramid;
  TsCandidateSet sets[16], again[16];

  ts_mrpm_options_init (&o);
  build_pyramid (lab, &pyramid);
  CHECK (pyramid.levels <= 16, "depth");
  memset (sets, 0, sizeof sets);
  memset (again, 0, sizeof again);
#ifdef _OPENMP
  omp_set_num_threads (1);
#endif
  double t1 = run_mrpm (&pyramid, &o, sets);
#ifdef _OPENMP
  omp_set_num_threads (2);
#endif
  double t2 = run_mrpm (&pyramid, &o, again);
  printf ("%s %zux%zu, %zu levels: MRPM %.1f ms (1 thread), %.1f ms (2 threads)\n",
          label, lab->width, lab->height, pyramid.levels, 1e3 * t1, 1e3 * t2);
  for (size_t l = 0; l < pyramid.levels; l++)
    {
      double recall, ratio;
      size_t n = sets[l].width * sets[l].height * sets[l].k;
      CHECK (sets[l].index && again[l].index
             && memcmp (sets[l].index, again[l].index, n * sizeof (int32_t)) == 0,
             "%s level %zu: 1 vs 2 threads differ", label, l);
      check_set (&pyramid, l, &sets[l], &o);
      compare_brute (&pyramid, l, &sets[l], &o, 500, &recall, &ratio);
      printf ("  level %zu (%zux%zu, k %zu): recall %.3f, distance ratio %.4f\n",
              l, sets[l].width, sets[l].height, sets[l].k, recall, ratio);
      int coarsest = l + 1 == pyramid.levels;
      CHECK (recall >= (coarsest ? MIN_RECALL_COARSEST : MIN_RECALL_FINER),
             "%s level %zu: recall %.3f", label, l, recall);
      CHECK (ratio <= MAX_RATIO, "%s level %zu: distance ratio %.4f", label, l, ratio);
    }
  free_sets (sets, pyramid.levels);
  free_sets (again, pyramid.levels);
  ts_pyramid_free (&pyramid);
}

/* Without PCA the coarsest level is an exact brute force: recall 1. */
static void
test_exact (const TsImage *lab)
{
  TsMrpmOptions o;
  TsPyramid pyramid;
  TsCandidateSet sets[16];

  ts_mrpm_options_init (&o);
  o.pca_dims = 0;
  build_pyramid (lab, &pyramid);
  memset (sets, 0, sizeof sets);
  run_mrpm (&pyramid, &o, sets);
  for (size_t l = 0; l < pyramid.levels; l++)
    {
      double recall, ratio;
      check_set (&pyramid, l, &sets[l], &o);
      compare_brute (&pyramid, l, &sets[l], &o, 300, &recall, &ratio);
      printf ("  exact search, level %zu: recall %.3f, distance ratio %.4f\n", l, recall, ratio);
      if (l + 1 == pyramid.levels)
        CHECK (recall > 0.999 && ratio < 1.0001, "exact brute force: recall %.4f ratio %.5f", recall, ratio);
    }
  free_sets (sets, pyramid.levels);
  ts_pyramid_free (&pyramid);
}

static void
crop (const TsImage *in, size_t x0, size_t y0, size_t w, size_t h, TsImage *out)
{
  CHECK (ts_image_alloc (out, w, h) == TS_OK, "alloc");
  for (size_t y = 0; y < h; y++)
    memcpy (ts_image_pixel (out, 0, y), ts_image_pixel (in, x0, y0 + y), w * TS_CHANNELS * sizeof (float));
}

/* A transparent block: no candidate may point into it at any level. */
static void
test_transparent (const TsImage *lab)
{
  TsImage copy;
  TsPyramid pyramid;
  TsCandidateSet sets[16];
  TsMrpmOptions o;

  crop (lab, 0, 0, lab->width, lab->height, &copy);
  for (size_t y = 20; y < 44; y++)
    for (size_t x = 10; x < 40; x++)
      ts_image_pixel (&copy, x, y)[3] = 0.0f;
  ts_mrpm_options_init (&o);
  build_pyramid (&copy, &pyramid);
  memset (sets, 0, sizeof sets);
  run_mrpm (&pyramid, &o, sets);
  size_t transparent = 0;
  for (size_t l = 0; l < pyramid.levels; l++)
    {
      const TsImage *im = &pyramid.level[l];
      for (size_t i = 0; i < im->width * im->height; i++)
        transparent += im->pixels[i * TS_CHANNELS + 3] == 0.0f;
      check_set (&pyramid, l, &sets[l], &o);
    }
  CHECK (transparent > 100, "the test block should leave transparent pixels (%zu)", transparent);
  free_sets (sets, pyramid.levels);
  ts_pyramid_free (&pyramid);
  ts_image_free (&copy);
}

/* 8x8 and 4x4 levels: the patch shrinks; unfillable entries are -1. */
static void
test_tiny (void)
{
  TsImage noise;
  TsPyramid pyramid;
  TsCandidateSet sets[2];
  TsMrpmOptions o;

  test_noise_image (&noise, 8, 8, 7);
  TsImage work;
  CHECK (ts_image_to_working (&noise, &work) == TS_OK, "to_working");
  CHECK (ts_pyramid_build (&work, 2, &pyramid) == TS_OK, "pyramid");
  ts_mrpm_options_init (&o);
  o.patch_size = 9;
  o.exclude_radius = 0;
  CHECK (ts_mrpm_radius (&pyramid, 0, &o) == 3 && ts_mrpm_radius (&pyramid, 1, &o) == 1, "shrunk radius");
  CHECK (ts_mrpm_level (&pyramid, 1, NULL, 5, &o, NULL, &sets[1]) == TS_OK, "tiny coarse");
  CHECK (ts_mrpm_level (&pyramid, 0, &sets[1], 6, &o, NULL, &sets[0]) == TS_OK, "tiny fine");
  check_set (&pyramid, 1, &sets[1], &o);
  check_set (&pyramid, 0, &sets[0], &o);
  /* 4x4 level with r = 1: 2x2 valid centres, so 3 candidates then -1. */
  CHECK (sets[1].index[0] >= 0 && sets[1].index[2] >= 0 && sets[1].index[3] == -1
         && sets[1].index[4] == -1, "-1 handling on 4x4");
  /* 8x8 level with r = 3: 2x2 valid centres. */
  CHECK (sets[0].index[2] >= 0 && sets[0].index[3] == -1, "-1 handling on 8x8");
  ts_candidate_set_free (&sets[0]);
  ts_candidate_set_free (&sets[1]);

  /* Exclusion larger than the level: every entry -1, still TS_OK. */
  o.exclude_radius = 4;
  CHECK (ts_mrpm_level (&pyramid, 1, NULL, 3, &o, NULL, &sets[1]) == TS_OK, "all excluded");
  for (size_t i = 0; i < 16 * 3; i++)
    CHECK (sets[1].index[i] == -1, "entry %zu should be -1", i);

  /* Mismatched coarser set, k = 0, cancellation. */
  ts_mrpm_options_init (&o);
  CHECK (ts_mrpm_level (&pyramid, 1, &sets[1], 3, &o, NULL, &sets[0]) == TS_ERROR_INVALID_ARGUMENT,
         "coarser of the wrong level");
  CHECK (ts_mrpm_level (&pyramid, 1, NULL, 0, &o, NULL, &sets[0]) == TS_ERROR_INVALID_ARGUMENT, "k = 0");
  TsCancel cancel;
  ts_cancel_init (&cancel, NULL, NULL);
  ts_cancel_request (&cancel);
  CHECK (ts_mrpm_level (&pyramid, 0, NULL, 3, &o, &cancel, &sets[0]) == TS_ERROR_CANCELLED
         && sets[0].index == NULL, "cancel");
  /* A callback asked from inside the search, saying stop. */
  int asked = 0;
  ts_cancel_init (&cancel, say_stop, &asked);
  cancel.last_ask = -1.0;  /* due at the first poll */
  CHECK (ts_mrpm_level (&pyramid, 0, NULL, 3, &o, &cancel, &sets[0]) == TS_ERROR_CANCELLED
         && sets[0].index == NULL && asked == 1, "cancel by the callback (asked %d times)", asked);
  ts_candidate_set_free (&sets[1]);
  ts_pyramid_free (&pyramid);
  ts_image_free (&work);
  free (noise.pixels);
}

int
main (void)
{
  TsImage bark, java, small;

  test_load_exemplar ("bark.png", &bark);
  test_load_exemplar ("java.png", &java);
  crop (&bark, 20, 30, 48, 48, &small);

  test_exemplar ("bark", &bark);
  test_exemplar ("java", &java);
  test_exemplar ("bark crop", &small);
  test_exact (&small);
  test_transparent (&java);
  test_tiny ();

  free (bark.pixels);
  free (java.pixels);
  ts_image_free (&small);
  return test_finish ("test-mrpm");
}
