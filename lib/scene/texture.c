/*
 * texture.c - the texture table and the texture sampler (see texture.h).
 *
 * The table is open addressing with linear probing on the name, the same
 * scheme as the object table (object.c): Fibonacci hashing, load factor
 * under 1/2, backward-shift deletion.
 */
#include "scene/texture.h"

#include <math.h>
#include <string.h>

#include "base/alloc.h"

/* First table size: a scene has far fewer textures than objects, so
 * smaller than the object table's 64 (object.c). */
#define TEXTURE_TABLE_MIN_CAPACITY 16u

void scene_textures_init(struct scene_textures *table)
{
    memset(table, 0, sizeof(*table));
    table->next_name = 1;
}

static void texture_free(struct scene_texture *tex)
{
    rt_free(tex->texels);
    rt_free(tex);
}

void scene_textures_release(struct scene_textures *table)
{
    for (uint32_t i = 0; i < table->capacity; i++)
        if (table->slots[i])
            texture_free(table->slots[i]);
    rt_free(table->slots);
    scene_textures_init(table);
}

static uint32_t slot_of(uint32_t capacity, uint32_t name)
{
    return (uint32_t)((name * 2654435769u) & (capacity - 1));
}

struct scene_texture *scene_textures_lookup(const struct scene_textures *table, uint32_t name)
{
    if (!table->capacity || name == 0)
        return NULL;
    for (uint32_t i = slot_of(table->capacity, name);; i = (i + 1) & (table->capacity - 1)) {
        struct scene_texture *tex = table->slots[i];
        if (!tex)
            return NULL;
        if (tex->name == name)
            return tex;
    }
}

static void insert_slot(struct scene_texture **slots, uint32_t capacity,
                        struct scene_texture *tex)
{
    uint32_t i = slot_of(capacity, tex->name);
    while (slots[i])
        i = (i + 1) & (capacity - 1);
    slots[i] = tex;
}

/* Keeps the load factor under 1/2; -1 on allocation failure (unchanged). */
static int ensure_room(struct scene_textures *table, uint32_t extra)
{
    uint64_t needed = ((uint64_t)table->used + extra) * 2;
    if (needed <= table->capacity)
        return 0;
    uint64_t cap = table->capacity ? table->capacity : TEXTURE_TABLE_MIN_CAPACITY;
    while (cap < needed)
        cap *= 2;
    if (cap > (1u << 31))
        return -1;
    struct scene_texture **slots = rt_calloc(cap, sizeof(*slots));
    if (!slots)
        return -1;
    for (uint32_t i = 0; i < table->capacity; i++)
        if (table->slots[i])
            insert_slot(slots, (uint32_t)cap, table->slots[i]);
    rt_free(table->slots);
    table->slots = slots;
    table->capacity = (uint32_t)cap;
    return 0;
}

/* A texture without an image and with the default parameters
 * (docs/textures.md: LINEAR for both filters, REPEAT in s and t). */
static struct scene_texture *texture_new(uint32_t name)
{
    struct scene_texture *tex = rt_calloc(1, sizeof(*tex));
    if (!tex)
        return NULL;
    tex->name = name;
    tex->min_filter = SCENE_FILTER_LINEAR;
    tex->mag_filter = SCENE_FILTER_LINEAR;
    tex->wrap_s = SCENE_WRAP_REPEAT;
    tex->wrap_t = SCENE_WRAP_REPEAT;
    return tex;
}

struct scene_texture *scene_textures_get_or_create(struct scene_textures *table, uint32_t name)
{
    struct scene_texture *tex = scene_textures_lookup(table, name);
    if (tex || name == 0)
        return tex;
    if (ensure_room(table, 1))
        return NULL;
    tex = texture_new(name);
    if (!tex)
        return NULL;
    insert_slot(table->slots, table->capacity, tex);
    table->used++;
    return tex;
}

int scene_textures_generate(struct scene_textures *table, uint32_t n, uint32_t *names)
{
    if (n == 0)
        return 0;
    if (n > (1u << 30) || ensure_room(table, n))
        return -1;
    struct scene_texture **fresh = rt_calloc(n, sizeof(*fresh));
    if (!fresh)
        return -1;
    uint32_t candidate = table->next_name;
    for (uint32_t i = 0; i < n; i++) {
        /* Skip 0 and names in use; the table is at most half full of
         * 2^32 - 1 names, so this terminates. */
        while (candidate == 0 || scene_textures_lookup(table, candidate))
            candidate++;
        fresh[i] = texture_new(candidate++);
        if (!fresh[i]) {
            for (uint32_t j = 0; j < i; j++)
                texture_free(fresh[j]);
            rt_free(fresh);
            return -1;
        }
    }
    /* Names go out only once every entry exists: a failure writes none. */
    for (uint32_t i = 0; i < n; i++) {
        insert_slot(table->slots, table->capacity, fresh[i]);
        table->used++;
        names[i] = fresh[i]->name;
    }
    table->next_name = candidate;
    rt_free(fresh);
    return 0;
}

void scene_textures_remove(struct scene_textures *table, uint32_t name)
{
    if (!table->capacity || name == 0)
        return;
    uint32_t mask = table->capacity - 1;
    uint32_t i = slot_of(table->capacity, name);
    while (table->slots[i] && table->slots[i]->name != name)
        i = (i + 1) & mask;
    struct scene_texture *tex = table->slots[i];
    if (!tex)
        return;
    table->used--;
    table->slots[i] = NULL;
    texture_free(tex);
    /* Backward-shift deletion keeps linear probing chains intact. */
    for (uint32_t j = (i + 1) & mask; table->slots[j]; j = (j + 1) & mask) {
        struct scene_texture *moved = table->slots[j];
        table->slots[j] = NULL;
        insert_slot(table->slots, table->capacity, moved);
    }
}

void scene_texture_set_image(struct scene_texture *tex, int width, int height, uint8_t *texels)
{
    rt_free(tex->texels);
    tex->width = width;
    tex->height = height;
    tex->texels = texels;
}

/* ---- sampling ------------------------------------------------------------ */

/*
 * The coordinate reduced to a range where scaling by the size cannot
 * overflow: REPEAT keeps the fractional part, s - floor(s), in [0, 1);
 * CLAMP_TO_EDGE bounds it to [-1, 2], which changes no lookup.  Computed
 * in double, where s - floor(s) is exact for every float s but a tiny
 * negative one.  NaN and infinities become 0.
 */
static double reduce_coord(float s, enum scene_texture_wrap wrap)
{
    double d = isfinite(s) ? (double)s : 0.0;
    if (wrap == SCENE_WRAP_REPEAT) {
        double f = d - floor(d);
        /* A tiny negative s has its fractional part just below 1, which
         * can round to 1: keep it in the last texel, where it belongs. */
        return f < 1.0 ? f : 0x1.fffffffffffffp-1;
    }
    return fmin(fmax(d, -1.0), 2.0);
}

/* Texel index i (any value in [-n - 1, 2n + 1]) mapped into [0, n). */
static int wrap_index(long i, int n, enum scene_texture_wrap wrap)
{
    if (wrap == SCENE_WRAP_REPEAT) {
        i %= n;
        return (int)(i < 0 ? i + n : i);
    }
    return i < 0 ? 0 : i >= n ? n - 1 : (int)i;
}

static void fetch_texel(const struct scene_texture *tex, int i, int j, float rgba[4])
{
    const uint8_t *p = &tex->texels[4 * ((size_t)j * (size_t)tex->width + (size_t)i)];
    /* Division, not a multiplication by 1/255: b / 255 is then the
     * correctly rounded value of the 8-bit colour, exactly what an
     * application computes for it. */
    for (int k = 0; k < 4; k++)
        rgba[k] = (float)p[k] / 255.0f;
}

void scene_texture_sample(const struct scene_texture *tex, enum scene_texture_filter filter,
                          float s, float t, float rgba[4])
{
    const int w = tex->width, h = tex->height;
    const double u = reduce_coord(s, tex->wrap_s) * w;
    const double v = reduce_coord(t, tex->wrap_t) * h;
    if (filter == SCENE_FILTER_NEAREST) {
        /* GL 1.1 eq. 3.16: the texel whose square contains (u, v). */
        int i = wrap_index((long)floor(u), w, tex->wrap_s);
        int j = wrap_index((long)floor(v), h, tex->wrap_t);
        fetch_texel(tex, i, j, rgba);
        return;
    }
    /* GL 1.1 eq. 3.17: i0 = floor(u - 1/2), alpha = frac(u - 1/2); the
     * four texels around the sample point, weighted bilinearly. */
    const double uc = u - 0.5, vc = v - 0.5;
    const double fi = floor(uc), fj = floor(vc);
    const float a = (float)(uc - fi), b = (float)(vc - fj);
    const int i0 = wrap_index((long)fi, w, tex->wrap_s);
    const int i1 = wrap_index((long)fi + 1, w, tex->wrap_s);
    const int j0 = wrap_index((long)fj, h, tex->wrap_t);
    const int j1 = wrap_index((long)fj + 1, h, tex->wrap_t);
    float c00[4], c10[4], c01[4], c11[4];
    fetch_texel(tex, i0, j0, c00);
    fetch_texel(tex, i1, j0, c10);
    fetch_texel(tex, i0, j1, c01);
    fetch_texel(tex, i1, j1, c11);
    /* The same weights as nested interpolations: where the four texels
     * agree the result is exactly their value (an opaque alpha stays 1). */
    for (int k = 0; k < 4; k++) {
        float bottom = c00[k] + a * (c10[k] - c00[k]);
        float top = c01[k] + a * (c11[k] - c01[k]);
        rgba[k] = bottom + b * (top - bottom);
    }
}
