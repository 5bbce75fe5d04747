/* Small helpers shared by the engine tests. */
#ifndef TS_TEST_UTIL_H
#define TS_TEST_UTIL_H

#include "texsynth.h"

#include <stdbool.h>
#include <stdio.h>

/* Sanitizer builds (scripts/sanitize.sh): the engine runs several times
 * slower and memory carries shadow and quarantine, so tests scale their
 * sizes and skip time and memory bounds there. */
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TEST_SANITIZED 1
#elif defined(__has_feature) /* clang */
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define TEST_SANITIZED 1
#endif
#endif

/* Small-size runs (TEXSYNTH_TEST_SMALL set and not "0"; scripts/sanitize.sh
 * sets it): tests run their engines on small sizes and one seed, to reach
 * the same code in a fraction of the time, and leave quality thresholds,
 * which hold only at full size, to the native run. */
bool test_small (void);

extern int ts_test_failures;

#define CHECK(cond, ...)                                                    \
  do {                                                                      \
    if (!(cond)) {                                                          \
      ts_test_failures++;                                                   \
      fprintf (stderr, "%s:%d: CHECK failed: %s: ", __FILE__, __LINE__, #cond); \
      fprintf (stderr, __VA_ARGS__);                                        \
      fputc ('\n', stderr);                                                 \
    }                                                                       \
  } while (0)

/* Exit status for main(): 0 if no CHECK failed. */
int test_finish (const char *name);

/* Loads `name` (e.g. "bark.png") from $TEXSYNTH_EXEMPLARS as Lab+alpha;
 * aborts the test with a message if it cannot. Free with free(). */
void test_load_exemplar (const char *name, TsImage *image);

/* A plain synthesis of `exemplar` filling `out` (its size as set there)
 * with the default parameters, the given seed, tileable or not; CHECKs
 * that it succeeds, naming the exemplar `name`. */
void test_synthesize (const char *name, const TsImage *exemplar, TsImage *out, uint32_t seed,
                      bool tileable);

/* Deterministic smooth-noise Lab image, opaque. */
void test_noise_image (TsImage *image, size_t width, size_t height, unsigned seed);

/* The process's peak resident set size so far, in KiB: a synthesis's
 * memory is the growth of this across it, taken before larger runs. */
long test_peak_rss_kib (void);

#endif
