/* 2D synthesis pastes no large piece of its exemplar: the largest copied
 * region (tools/metrics.c, `copy`) of every result stays at most half
 * the exemplar's area. Near-regular exemplars are where copies grew
 * largest (bundled brick and burlap at 256x256: up to 0.72 and 0.67
 * before the engine bounded them), large outputs too (granite1 0.50 at
 * 1024x1024); tileable results, left unbounded, stay below (brick
 * 0.32-0.42).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "metrics.h"
#include "test-util.h"

#include <stdio.h>
#include <stdlib.h>

/* The bound asked of a result: half the exemplar. */
#define MAX_COPY 0.5

static void
check_copy (const char *name, size_t side, uint32_t seeds, bool tileable)
{
  TsImage exemplar, out = { side, side, NULL };

  test_load_exemplar (name, &exemplar);
  out.pixels = malloc (side * side * TS_CHANNELS * sizeof (float));
  CHECK (out.pixels != NULL, "out of memory");
  for (uint32_t seed = 1; out.pixels && seed <= seeds; seed++)
    {
      double copy = 2.0;
      test_synthesize (name, &exemplar, &out, seed, tileable);
      CHECK (ts_measure_copy (&exemplar, &out, tileable, tileable, &copy) == TS_MEASURE_OK,
             "%s seed %u measured", name, seed);
      printf ("%s %zux%zu%s seed %u: copy %.3f\n", name, side, side, tileable ? " tileable" : "",
              seed, copy);
      CHECK (copy <= MAX_COPY, "%s %zux%zu%s seed %u: copy %.3f above %.2f", name, side, side,
             tileable ? " tileable" : "", seed, copy, MAX_COPY);
    }
  free (out.pixels);
  free (exemplar.pixels);
}

int
main (void)
{
  uint32_t seeds = test_small () ? 1 : 3;

  check_copy ("brick.png", 256, seeds, false);
  check_copy ("burlap.png", 256, seeds, false);
  check_copy ("brick.png", 256, seeds, true);
  check_copy ("granite1.png", test_small () ? 256 : 1024, 1, false);
  return test_finish ("test-copy-bound");
}
