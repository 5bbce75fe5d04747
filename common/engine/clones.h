/* Versions of a hot function for wider vectors (internal).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#ifndef TS_CLONES_H
#define TS_CLONES_H

/* On x86-64 with GCC, a function marked TS_VECTOR_CLONES is compiled for
 * the baseline and for x86-64-v3 (AVX2), and the loader picks the one the
 * CPU runs. Both give the same bits: the marked code's arithmetic is
 * lane-wise, and ISO C mode leaves multiply-adds uncontracted. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__linux__)
#define TS_VECTOR_CLONES __attribute__ ((target_clones ("arch=x86-64-v3", "default")))
#else
#define TS_VECTOR_CLONES
#endif

/* A helper of a TS_VECTOR_CLONES function, inlined into each clone so
 * that it is compiled for that clone's vectors too (left out of line,
 * it would run the baseline's). */
#if defined(__GNUC__)
#define TS_CLONE_INLINE static inline __attribute__ ((always_inline))
#else
#define TS_CLONE_INLINE static inline
#endif

#endif
