/* Random numbers (internal; the tools and tests use them too). The
 * synthesis's are counter-based: every value is a pure function of (seed,
 * level, iteration, pixel, stream), so results never depend on thread
 * scheduling.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_RNG_H
#define TS_RNG_H

#include <stdint.h>

static inline uint64_t
ts_mix64 (uint64_t z)
{
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

static inline uint64_t
ts_random (uint32_t seed, uint32_t level, uint32_t iteration, uint64_t pixel, uint32_t stream)
{
  uint64_t h = ts_mix64 (((uint64_t) seed << 32 | level) + 0x9e3779b97f4a7c15ULL);
  h = ts_mix64 (h ^ ((uint64_t) iteration << 32 | stream));
  return ts_mix64 (h ^ pixel);
}

/* Uniform integer in [0, n), n > 0. */
static inline uint64_t
ts_random_below (uint64_t r, uint64_t n)
{
  return (uint64_t) (((unsigned __int128) r * n) >> 64);
}

/* A small sequential generator for fixed starting points and test
 * fixtures (Numerical Recipes' 32-bit LCG): advances `state` and returns
 * its top 24 bits. Not for the synthesis: its values depend on call order. */
static inline uint32_t
ts_lcg_next24 (uint32_t *state)
{
  *state = *state * 1664525u + 1013904223u;
  return *state >> 8;
}

#endif
