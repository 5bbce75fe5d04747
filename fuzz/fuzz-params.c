/* libFuzzer target: parameter validation, the memory estimate, and small
 * random exemplars through ts_synthesize, ts_make_tileable and ts_heal
 * (a hole from the input's bits; pixels outside it must come back as
 * they were, bit for bit). The input
 * bytes are the parameters (any values, in range or not), then the
 * exemplar's size and pixels (any floats: NaN, Inf, huge, negative).
 * Whatever the input, the engine must return a status with a message
 * and, on success, a finite result; sanitizers catch the rest.
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "texsynth.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Keeps each run to milliseconds: the fuzzer should spend its time on
 * many inputs, not on one large synthesis. */
#define MAX_EXEMPLAR_SIDE 24
#define MAX_RUN_OUTPUT_SIDE 32

typedef struct
{
  const uint8_t *data;
  size_t         size;
} Bytes;

static uint32_t
take_u32 (Bytes *b)
{
  uint32_t v = 0;
  for (int i = 0; i < 4 && b->size; i++, b->data++, b->size--)
    v |= (uint32_t) b->data[0] << (8 * i);
  return v;
}

static uint8_t
take_u8 (Bytes *b)
{
  uint8_t v = b->size ? b->data[0] : 0;
  if (b->size)
    {
      b->data++;
      b->size--;
    }
  return v;
}

/* Small values most of the time (so syntheses run), any value sometimes. */
static int
take_int (Bytes *b, int small_range)
{
  uint8_t mode = take_u8 (b);
  uint32_t raw = take_u32 (b);
  return mode < 224 ? (int) (raw % (uint32_t) small_range) : (int) raw;
}

static void
check_finite (const TsImage *image)
{
  for (size_t i = 0; i < image->width * image->height * TS_CHANNELS; i++)
    if (!isfinite (image->pixels[i]))
      abort ();
}

static void
check_message (TsStatus status, const TsError *error)
{
  if (status != TS_OK && error->message[0] == '\0')
    abort ();   /* every failure must say why */
}

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  Bytes b = { data, size };
  TsParams p;
  TsTileableParams tp;
  TsImage ex = { 0, 0, NULL }, out = { 0, 0, NULL };
  TsError error = { TS_OK, "" };
  size_t bytes;
  TsStatus status;
  uint8_t flags = take_u8 (&b);

  ts_params_init (&p);
  p.output_width = (size_t) take_int (&b, MAX_RUN_OUTPUT_SIDE + 2);
  p.output_height = (size_t) take_int (&b, MAX_RUN_OUTPUT_SIDE + 2);
  if (flags & 0x80)
    p.output_width = (size_t) take_u32 (&b) << (take_u8 (&b) & 31);
  p.wrap_x = flags & 1;
  p.wrap_y = flags & 2;
  p.histogram_matching = flags & 4;
  p.quality = take_int (&b, TS_MAX_QUALITY + 2);
  p.seed = take_u32 (&b);
  p.patch_size = take_int (&b, TS_MAX_PATCH_SIZE + 3);
  p.fine_patch_size = take_int (&b, TS_MAX_PATCH_SIZE + 3);
  p.max_iterations = take_int (&b, 4);
  p.memory_limit = flags & 8 ? (size_t) take_u32 (&b) << 8 : 0;

  ex.width = take_u8 (&b) % (MAX_EXEMPLAR_SIDE + 1);
  ex.height = take_u8 (&b) % (MAX_EXEMPLAR_SIDE + 1);
  if (ex.width * ex.height > 0)
    {
      size_t floats = ex.width * ex.height * TS_CHANNELS;
      ex.pixels = malloc (floats * sizeof (float));
      if (!ex.pixels)
        return 0;
      for (size_t i = 0; i < floats; i++)
        {
          /* Raw float bits where the input has them, else a plain pattern. */
          uint32_t bits = b.size >= 4 ? take_u32 (&b) : 0x42480000u + (uint32_t) i * 977u;
          float v;
          memcpy (&v, &bits, sizeof v);
          if (i % 4 == 3 && b.size == 0)
            v = 1.0f;
          ex.pixels[i] = v;
        }
    }

  status = ts_estimate_memory (&p, &ex, &bytes, &error);
  check_message (status, &error);
  status = ts_params_validate (&p, &ex, &error);
  check_message (status, &error);

  if (status == TS_OK && p.output_width <= MAX_RUN_OUTPUT_SIDE && p.output_height <= MAX_RUN_OUTPUT_SIDE)
    {
      out.width = p.output_width;
      out.height = p.output_height;
      out.pixels = malloc (out.width * out.height * TS_CHANNELS * sizeof (float));
      if (out.pixels)
        {
          status = ts_synthesize (&p, &ex, &out, NULL, NULL, &error);
          check_message (status, &error);
          if (status == TS_OK)
            check_finite (&out);
        }
      free (out.pixels);
    }

  /* The same exemplar made tileable, when it is small enough. */
  ts_tileable_params_init (&tp);
  tp.direction = (TsTileableDirection) (flags >> 4 & 3);
  tp.seam_width = (double) (flags >> 6) * 0.08 + 0.01;
  tp.quality = p.quality;
  tp.seed = p.seed;
  tp.patch_size = p.patch_size;
  tp.fine_patch_size = p.fine_patch_size;
  tp.max_iterations = p.max_iterations;
  tp.memory_limit = p.memory_limit;
  if (ex.pixels && ts_tileable_params_validate (&tp, &ex, &error) == TS_OK)
    {
      out.width = ex.width;
      out.height = ex.height;
      out.pixels = malloc (out.width * out.height * TS_CHANNELS * sizeof (float));
      if (out.pixels)
        {
          status = ts_make_tileable (&tp, &ex, &out, NULL, NULL, &error);
          check_message (status, &error);
          if (status == TS_OK)
            check_finite (&out);
        }
      free (out.pixels);
    }
  /* The same image healed: hole, context and sampling from the input. */
  if (ex.pixels || flags & 0x40)
    {
      TsHealParams hp;
      size_t n = ex.width * ex.height;
      uint8_t hole_bits = take_u8 (&b), *hole = malloc (n ? n : 1);
      ts_heal_params_init (&hp);
      hp.context = (size_t) take_int (&b, 12);
      hp.sample_from = (TsHealSampleFrom) (take_u8 (&b) % 4);
      hp.quality = p.quality;
      hp.seed = p.seed;
      hp.patch_size = p.patch_size;
      hp.fine_patch_size = p.fine_patch_size;
      hp.memory_limit = p.memory_limit;
      for (size_t i = 0; hole && i < n; i++)
        hole[i] = hole_bits & 1 ? (i * 2654435761u >> (hole_bits >> 4)) % 5 == 0
                                : (i % (ex.width ? ex.width : 1)) * 3 / (ex.width + 1) == 1;
      status = hole ? ts_heal_estimate_memory (&hp, &ex, hole, NULL, &bytes, &error) : TS_OK;
      check_message (status, &error);
      if (hole && ts_heal_params_validate (&hp, &ex, hole, NULL, &error) == TS_OK)
        {
          out.width = ex.width;
          out.height = ex.height;
          out.pixels = malloc ((n ? n : 1) * TS_CHANNELS * sizeof (float));
          if (out.pixels)
            {
              status = ts_heal (&hp, &ex, hole, NULL, &out, NULL, NULL, NULL, &error);
              check_message (status, &error);
              for (size_t i = 0; status == TS_OK && i < n; i++)
                if (!hole[i] && memcmp (out.pixels + i * TS_CHANNELS, ex.pixels + i * TS_CHANNELS,
                                        TS_CHANNELS * sizeof (float)) != 0)
                  abort ();
            }
          free (out.pixels);
        }
      else if (hole)
        check_message (ts_heal_params_validate (&hp, &ex, hole, NULL, &error), &error);
      free (hole);
    }
  /* The same exemplar guided: guides of raw float bits (NaN and
   * infinities included) or flat labels, each way of comparing, any
   * weight; without an exemplar guide, style transfer. */
  if (ex.pixels && b.size > 0)
    {
      uint8_t g_flags = take_u8 (&b);
      size_t n_ex = ex.width * ex.height, n_out;
      TsGuides guides;
      ts_guides_init (&guides);
      /* Sizes the run can afford: the checks of huge sizes are above. */
      p.output_width = 1 + (size_t) (take_u8 (&b) % MAX_RUN_OUTPUT_SIDE);
      p.output_height = 1 + (size_t) (take_u8 (&b) % MAX_RUN_OUTPUT_SIDE);
      p.initial_source = NULL;
      p.preserve = NULL;
      n_out = p.output_width * p.output_height;
      guides.compare = (TsGuideCompare) (g_flags % 4);
      guides.channels = 1 + (size_t) (g_flags >> 2 & 3);
      guides.weight = (double) take_u8 (&b) / 16.0 - 1.0;
      float *ex_guide = malloc (n_ex * guides.channels * sizeof (float));
      float *target_guide = malloc (n_out * guides.channels * sizeof (float));
      if (ex_guide && target_guide)
        {
          for (size_t i = 0; i < n_ex * guides.channels; i++)
            ex_guide[i] = g_flags & 16 ? (float) (i / guides.channels % 3) : ex.pixels[i % (n_ex * TS_CHANNELS)];
          for (size_t i = 0; i < n_out * guides.channels; i++)
            {
              /* Raw float bits where the input has them, else labels 0 and 1. */
              uint32_t bits = b.size >= 4 ? take_u32 (&b) : 0;
              float v = (float) ((i * 2654435761u) >> 31 & 1u);
              if (bits)
                memcpy (&v, &bits, sizeof v);
              target_guide[i] = v;
            }
          guides.exemplar_guide = g_flags & 32 ? NULL : ex_guide;
          guides.target_guide = target_guide;
          p.guides = &guides;
          p.source_map = NULL;
          status = ts_params_validate (&p, &ex, &error);
          check_message (status, &error);
          out.width = p.output_width;
          out.height = p.output_height;
          out.pixels = status == TS_OK ? malloc (n_out * TS_CHANNELS * sizeof (float)) : NULL;
          if (out.pixels)
            {
              status = ts_synthesize (&p, &ex, &out, NULL, NULL, &error);
              check_message (status, &error);
              if (status == TS_OK)
                check_finite (&out);
            }
          free (out.pixels);
        }
      free (ex_guide);
      free (target_guide);
    }
  free (ex.pixels);
  return 0;
}
