/* Texture by numbers in layers. A label's region of the target may be
 * thinner than the coarse levels' neighbourhoods: there one guided
 * optimization sees too little of it to lay out its texture, and the
 * region comes out less coherent than that texture synthesised alone.
 * So each label's region is cut from a plain synthesis of its own
 * texture (the exemplar's pixels of that label, the rest transparent)
 * as large as the region's bounding box, and the label edges are the
 * target's. Synthesising a band along the edges again under the guide,
 * from this map, made the thin regions less coherent again, even a band
 * of one pixel (docs/guided.md).
 * SPDX-License-Identifier: LGPL-3.0-or-later */
#include "guide-layers.h"
#include "guide-params.h"
#include "image.h"
#include "synthesize.h"
#include "error.h"
#include "rng.h"

#include <stdlib.h>
#include <string.h>

/* A layer's exemplar is the bounding box of its label's pixels, grown to
 * at least this side where the exemplar allows: the finest level's large
 * neighbourhood (schedule.c), so that a label of a few pixels still
 * makes an exemplar the synthesis can match windows in. */
#define TS_LAYER_MIN_SIDE 11
/* Random stream of the layers' seeds (rng.h). */
#define TS_LAYER_SEED_STREAM 11
/* Each separate area of a label is synthesised over its own bounding
 * box, so that a label scattered over the target costs about its own
 * area, not its whole bounding box once per label. The box is grown to
 * at least the size of the label's part of the exemplar, so that the
 * synthesis has room for that texture's largest structures (a thin
 * stripe of a box lays them out badly), and areas whose boxes come
 * within the finest large neighbourhood of each other share one
 * synthesis. A label of more areas than this (the specks of a painted
 * map) is synthesised over its whole bounding box at once: each
 * synthesis has a fixed cost, its exemplar's pyramid and candidates. */
#define TS_LAYER_MAX_AREAS 64

typedef struct
{
  size_t x0, y0, x1, y1; /* x1, y1 exclusive */
} Box;

typedef struct
{
  TsProgressFunc func;
  void          *user_data;
  double         start, span;
} Part;

static bool
part_report (double fraction, const char *stage, void *data)
{
  const Part *part = data;
  return part->func (part->start + part->span * fraction, stage, part->user_data);
}

/* Each pixel's label: the exemplar guide's distinct values, and the
 * nearest of them for each target pixel. */
static TsStatus
label_maps (const TsParams *params, const TsImage *exemplar, uint8_t **ex_label,
            uint8_t **target_label, size_t *count)
{
  const TsGuides *g = params->guides;
  float table[TS_MAX_GUIDE_LABELS * TS_MAX_GUIDE_CHANNELS];
  size_t ex_n = exemplar->width * exemplar->height;
  size_t out_n = params->output_width * params->output_height;

  if (!ts_guide_find_labels (g->exemplar_guide, ex_n, g->channels, table, TS_MAX_GUIDE_LABELS,
                             count))
    return TS_ERROR_BAD_PARAMETER;
  *ex_label = malloc (ex_n);
  *target_label = malloc (out_n);
  if (!*ex_label || !*target_label)
    return TS_ERROR_OUT_OF_MEMORY;
#pragma omp parallel for schedule(static)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) ex_n; i++)
    (*ex_label)[i] = ts_guide_nearest_label (table, *count, g->channels,
                                             g->exemplar_guide + (size_t) i * g->channels);
  /* A distinct value that no exemplar pixel is nearest to (a NaN, or one
   * within float underflow of an earlier label) has no texture to grow:
   * only the labels the exemplar has stay. */
  uint8_t kept[TS_MAX_GUIDE_LABELS] = { 0 }, index[TS_MAX_GUIDE_LABELS];
  size_t present = 0;
  for (size_t i = 0; i < ex_n; i++)
    kept[(*ex_label)[i]] = 1;
  for (size_t l = 0; l < *count; l++)
    if (kept[l])
      {
        index[l] = (uint8_t) present;
        memmove (table + present * g->channels, table + l * g->channels,
                 g->channels * sizeof (float));
        present++;
      }
  if (present < *count)
    for (size_t i = 0; i < ex_n; i++)
      (*ex_label)[i] = index[(*ex_label)[i]];
  *count = present;
#pragma omp parallel for schedule(static)
  for (ptrdiff_t i = 0; i < (ptrdiff_t) out_n; i++)
    (*target_label)[i] = ts_guide_nearest_label (table, *count, g->channels,
                                                 g->target_guide + (size_t) i * g->channels);
  return TS_OK;
}

/* Bounding boxes of labels 0 .. count-1 in a w x h map, in one pass; a
 * label without pixels gets an empty box (x1 <= x0). */
static void
bounding_boxes (const uint8_t *map, size_t w, size_t h, size_t count, Box *box)
{
  for (size_t l = 0; l < count; l++)
    box[l] = (Box) { w, h, 0, 0 };
  for (size_t y = 0; y < h; y++)
    for (size_t x = 0; x < w; x++)
      {
        Box *b = &box[map[y * w + x]];
        b->x0 = x < b->x0 ? x : b->x0;
        b->x1 = x + 1 > b->x1 ? x + 1 : b->x1;
        b->y0 = y < b->y0 ? y : b->y0;
        b->y1 = y + 1 > b->y1 ? y + 1 : b->y1;
      }
}

/* `b` grown on both sides to at least min_w x min_h, within w x h. */
static void
grow_box (Box *b, size_t w, size_t h, size_t min_w, size_t min_h)
{
  size_t side_w = w < min_w ? w : min_w, side_h = h < min_h ? h : min_h;

  while (b->x1 - b->x0 < side_w)
    {
      b->x0 -= b->x0 > 0;
      b->x1 += b->x1 < w && b->x1 - b->x0 < side_w;
    }
  while (b->y1 - b->y0 < side_h)
    {
      b->y0 -= b->y0 > 0;
      b->y1 += b->y1 < h && b->y1 - b->y0 < side_h;
    }
}

static size_t
box_area (const Box *b)
{
  return (b->x1 - b->x0) * (b->y1 - b->y0);
}

/* The exemplar's pixels of `label` inside their bounding box `eb`, the
 * others made transparent, so a synthesis from it uses that texture
 * alone. */
static TsStatus
layer_exemplar (const TsImage *exemplar, const uint8_t *ex_label, uint8_t label, const Box *eb,
                TsImage *layer)
{
  layer->width = eb->x1 - eb->x0;
  layer->height = eb->y1 - eb->y0;
  layer->pixels = malloc (layer->width * layer->height * TS_CHANNELS * sizeof (float));
  if (!layer->pixels)
    return TS_ERROR_OUT_OF_MEMORY;
  for (size_t y = 0; y < layer->height; y++)
    for (size_t x = 0; x < layer->width; x++)
      {
        size_t s = (eb->y0 + y) * exemplar->width + eb->x0 + x;
        float *d = layer->pixels + (y * layer->width + x) * TS_CHANNELS;
        memcpy (d, exemplar->pixels + s * TS_CHANNELS, TS_CHANNELS * sizeof (float));
        if (ex_label[s] != label)
          d[3] = 0.0f;
      }
  return TS_OK;
}

/* Sources of `label`'s pixels that a layer took from the exemplar's
 * transparent part (another label's pixels) continue a neighbour's copy
 * instead: the neighbour's source moved by the step between them, if
 * that pixel has the label. Passes sweep down and up until none is left
 * or a pass mends nothing; the rest take the label's first pixel. */
static void
mend_sources (const TsParams *params, const TsImage *exemplar, const uint8_t *ex_label,
              const uint8_t *target_label, uint8_t label, const Box *ob, int32_t *start)
{
  size_t out_w = params->output_width, ew = exemplar->width, eh = exemplar->height;
  static const int step[4][2] = { { -1, 0 }, { 0, -1 }, { 1, 0 }, { 0, 1 } };
  bool left = true;

  for (size_t pass = 0; left; pass++)
    {
      size_t mended = 0;
      left = false;
      for (size_t i = 0; i < box_area (ob); i++)
        {
          size_t k = pass % 2 ? box_area (ob) - 1 - i : i;
          size_t x = ob->x0 + k % (ob->x1 - ob->x0), y = ob->y0 + k / (ob->x1 - ob->x0);
          int32_t *s = start + 2 * (y * out_w + x);
          if (target_label[y * out_w + x] != label ||
              ex_label[(size_t) s[1] * ew + (size_t) s[0]] == label)
            continue;
          for (size_t d = 0; d < 4; d++)
            {
              ptrdiff_t nx = (ptrdiff_t) x + step[d][0], ny = (ptrdiff_t) y + step[d][1];
              if (nx < (ptrdiff_t) ob->x0 || ny < (ptrdiff_t) ob->y0 ||
                  nx >= (ptrdiff_t) ob->x1 || ny >= (ptrdiff_t) ob->y1 ||
                  target_label[(size_t) ny * out_w + (size_t) nx] != label)
                continue;
              const int32_t *n = start + 2 * ((size_t) ny * out_w + (size_t) nx);
              ptrdiff_t sx = n[0] - step[d][0], sy = n[1] - step[d][1];
              if (ex_label[(size_t) n[1] * ew + (size_t) n[0]] == label && sx >= 0 && sy >= 0 &&
                  sx < (ptrdiff_t) ew && sy < (ptrdiff_t) eh &&
                  ex_label[(size_t) sy * ew + (size_t) sx] == label)
                {
                  s[0] = (int32_t) sx;
                  s[1] = (int32_t) sy;
                  mended++;
                  break;
                }
            }
          left = left || ex_label[(size_t) s[1] * ew + (size_t) s[0]] != label;
        }
      if (left && mended == 0)
        break;
    }
  if (!left)
    return;
  size_t first = 0;
  while (ex_label[first] != label)
    first++;
  for (size_t y = ob->y0; y < ob->y1; y++)
    for (size_t x = ob->x0; x < ob->x1; x++)
      {
        int32_t *s = start + 2 * (y * out_w + x);
        if (target_label[y * out_w + x] == label &&
            ex_label[(size_t) s[1] * ew + (size_t) s[0]] != label)
          {
            s[0] = (int32_t) (first % ew);
            s[1] = (int32_t) (first / ew);
          }
      }
}

/* A plain synthesis of `label`'s texture (`layer`: layer_exemplar's, of
 * the exemplar's box `eb`) over the box `ob` of the output (the label's
 * `area`-th); its sources go to start[] at the pixels the target gives
 * that label, in the whole exemplar's coordinates. */
static TsStatus
synthesize_layer (const TsParams *params, const TsImage *exemplar, const uint8_t *ex_label,
                  const TsImage *layer, const Box *eb, const uint8_t *target_label,
                  uint8_t label, uint32_t area, const Box *ob, int32_t *start,
                  TsExemplarMemo *memo, Part *part, TsError *error)
{
  size_t out_w = params->output_width;
  TsImage result = { ob->x1 - ob->x0, ob->y1 - ob->y0, NULL };
  int32_t *sources = NULL;
  uint8_t *needed = NULL;
  TsParams p = *params;
  TsStatus status = TS_OK;

  result.pixels = malloc (result.width * result.height * TS_CHANNELS * sizeof (float));
  sources = malloc (result.width * result.height * 2 * sizeof (int32_t));
  needed = malloc (result.width * result.height);
  if (status == TS_OK && (!result.pixels || !sources || !needed))
    status = TS_ERROR_OUT_OF_MEMORY;
  /* Only the label's own pixels of the box are kept: the synthesis
   * optimizes them and their neighbourhoods, not the whole box. */
  for (size_t y = ob->y0; status == TS_OK && y < ob->y1; y++)
    for (size_t x = ob->x0; x < ob->x1; x++)
      needed[(y - ob->y0) * result.width + x - ob->x0] = target_label[y * out_w + x] == label;
  if (status == TS_OK)
    {
      p.output_width = result.width;
      p.output_height = result.height;
      p.wrap_x = params->wrap_x && result.width == params->output_width;
      p.wrap_y = params->wrap_y && result.height == params->output_height;
      p.seed = (uint32_t) ts_random (params->seed, 0, area, label, TS_LAYER_SEED_STREAM);
      p.guides = NULL;
      p.source_map = sources;
      status = ts_params_validate (&p, layer, error);
      if (status == TS_OK)
        status = ts_synthesize_needed (&p, layer, needed, memo, &result,
                                       part->func ? part_report : NULL, part, error);
    }
  if (status == TS_OK)
    for (size_t y = ob->y0; y < ob->y1; y++)
      for (size_t x = ob->x0; x < ob->x1; x++)
        if (target_label[y * out_w + x] == label)
          {
            const int32_t *s = sources + 2 * ((y - ob->y0) * result.width + x - ob->x0);
            start[2 * (y * out_w + x)] = s[0] + (int32_t) eb->x0;
            start[2 * (y * out_w + x) + 1] = s[1] + (int32_t) eb->y0;
          }
  if (status == TS_OK)
    mend_sources (params, exemplar, ex_label, target_label, label, ob, start);
  free (result.pixels);
  free (sources);
  free (needed);
  return status;
}

/* Whether boxes a and b, each grown by `gap`, overlap. */
static bool
boxes_near (const Box *a, const Box *b, size_t gap)
{
  return a->x0 < b->x1 + gap && b->x0 < a->x1 + gap && a->y0 < b->y1 + gap &&
         b->y0 < a->y1 + gap;
}

/* The bounding boxes of the separate areas of `label` in the target
 * (4-connected, across a wrapped side too), each grown to at least
 * min_w x min_h, those near each other joined; false if there are more
 * than TS_LAYER_MAX_AREAS. `seen` and `stack` hold a byte and a size_t
 * per output pixel. */
static bool
label_areas (const TsParams *params, const uint8_t *target_label, uint8_t label, size_t min_w,
             size_t min_h, uint8_t *seen, size_t *stack, Box *area, size_t *count)
{
  size_t w = params->output_width, h = params->output_height, n = w * h;

  *count = 0;
  memset (seen, 0, n);
  for (size_t start = 0; start < n; start++)
    {
      if (seen[start] || target_label[start] != label)
        continue;
      if (*count == TS_LAYER_MAX_AREAS)
        return false;
      Box b = { w, h, 0, 0 };
      size_t top = 0;
      stack[top++] = start;
      seen[start] = 1;
      while (top > 0)
        {
          size_t p = stack[--top], x = p % w, y = p / w;
          size_t next[4];
          int k = 0;
          b.x0 = x < b.x0 ? x : b.x0;
          b.x1 = x + 1 > b.x1 ? x + 1 : b.x1;
          b.y0 = y < b.y0 ? y : b.y0;
          b.y1 = y + 1 > b.y1 ? y + 1 : b.y1;
          if (x > 0 || params->wrap_x)
            next[k++] = y * w + (x > 0 ? x - 1 : w - 1);
          if (x + 1 < w || params->wrap_x)
            next[k++] = y * w + (x + 1 < w ? x + 1 : 0);
          if (y > 0 || params->wrap_y)
            next[k++] = (y > 0 ? y - 1 : h - 1) * w + x;
          if (y + 1 < h || params->wrap_y)
            next[k++] = (y + 1 < h ? y + 1 : 0) * w + x;
          for (int i = 0; i < k; i++)
            if (!seen[next[i]] && target_label[next[i]] == label)
              {
                seen[next[i]] = 1;
                stack[top++] = next[i];
              }
        }
      grow_box (&b, w, h, min_w, min_h);
      area[(*count)++] = b;
    }
  /* Join boxes near each other until none are. */
  for (size_t i = 0; i < *count; i++)
    for (size_t j = i + 1; j < *count; j++)
      if (boxes_near (&area[i], &area[j], TS_LAYER_MIN_SIDE / 2))
        {
          Box *a = &area[i], *b = &area[j];
          a->x0 = a->x0 < b->x0 ? a->x0 : b->x0;
          a->y0 = a->y0 < b->y0 ? a->y0 : b->y0;
          a->x1 = a->x1 > b->x1 ? a->x1 : b->x1;
          a->y1 = a->y1 > b->y1 ? a->y1 : b->y1;
          area[j] = area[--*count];
          i = (size_t) -1; /* start over: the grown box may now be near others */
          break;
        }
  return true;
}

/* The result and the caller's source map from the layers' sources. */
static void
write_layers (const TsParams *params, const TsImage *exemplar, const int32_t *start,
              TsImage *output)
{
  size_t n = params->output_width * params->output_height;

  ts_copy_by_source_map (exemplar, start, output);
  if (params->source_map)
    memcpy (params->source_map, start, n * 2 * sizeof (int32_t));
}

TsStatus
ts_guide_layers_synthesize (const TsParams *params, const TsImage *exemplar, TsImage *output,
                            TsProgressFunc progress, void *user_data, TsError *error)
{
  size_t out_w = params->output_width, out_h = params->output_height, n = out_w * out_h;
  size_t count = 0, areas[TS_MAX_GUIDE_LABELS];
  uint8_t *ex_label = NULL, *target_label = NULL, *seen = malloc (n);
  size_t *stack = malloc (n * sizeof (size_t));
  int32_t *start = malloc (n * 2 * sizeof (int32_t));
  Box box[TS_MAX_GUIDE_LABELS], ex_box[TS_MAX_GUIDE_LABELS];
  Box *area = malloc (TS_MAX_GUIDE_LABELS * TS_LAYER_MAX_AREAS * sizeof (Box));
  double total = 0.0, done = 0.0;
  Part part = { progress, user_data, 0.0, 0.0 };
  TsStatus status = start && seen && stack && area ? TS_OK : TS_ERROR_OUT_OF_MEMORY;

  if (status == TS_OK)
    status = label_maps (params, exemplar, &ex_label, &target_label, &count);
  if (status != TS_OK)
    ts_fail (error, status, "%s", ts_status_string (status));
  if (status == TS_OK)
    {
      bounding_boxes (target_label, out_w, out_h, count, box);
      bounding_boxes (ex_label, exemplar->width, exemplar->height, count, ex_box);
    }
  /* Each label's areas, or its whole box; progress counts their areas. */
  for (size_t l = 0; status == TS_OK && l < count; l++)
    {
      Box *mine = area + l * TS_LAYER_MAX_AREAS;
      areas[l] = 0;
      if (box[l].x1 <= box[l].x0)
        continue;
      if (!label_areas (params, target_label, (uint8_t) l, ex_box[l].x1 - ex_box[l].x0,
                        ex_box[l].y1 - ex_box[l].y0, seen, stack, mine, &areas[l]))
        {
          mine[0] = box[l];
          areas[l] = 1;
        }
      for (size_t a = 0; a < areas[l]; a++)
        total += (double) box_area (&mine[a]);
    }
  /* A label's areas share its part of the exemplar: it is cut out and
   * matched once. */
  for (size_t l = 0; status == TS_OK && l < count; l++)
    {
      TsExemplarMemo memo = { 0 };
      TsImage layer = { 0 };
      Box eb = ex_box[l];
      if (areas[l] == 0)
        continue;
      grow_box (&eb, exemplar->width, exemplar->height, TS_LAYER_MIN_SIDE, TS_LAYER_MIN_SIDE);
      status = layer_exemplar (exemplar, ex_label, (uint8_t) l, &eb, &layer);
      if (status != TS_OK)
        ts_fail (error, status, "%s", ts_status_string (status));
      for (size_t a = 0; status == TS_OK && a < areas[l]; a++)
        {
          const Box *b = &area[l * TS_LAYER_MAX_AREAS + a];
          part.start = done / total;
          part.span = (double) box_area (b) / total;
          status = synthesize_layer (params, exemplar, ex_label, &layer, &eb, target_label,
                                     (uint8_t) l, (uint32_t) a, b, start, &memo, &part, error);
          done += (double) box_area (b);
        }
      ts_exemplar_memo_free (&memo);
      free (layer.pixels);
    }
  if (status == TS_OK)
    write_layers (params, exemplar, start, output);
  free (ex_label);
  free (target_label);
  free (seen);
  free (stack);
  free (start);
  free (area);
  return status;
}
