/* SPDX-License-Identifier: Apache-2.0 */
/*
 * aff_parse.c - the AFF text reader (see aff_internal.h).
 *
 * Follows FORMAT.md (the BART format description beside the data):
 *   sec. 2   the reader is not line based: at statement level it reads one
 *            character, which (with a look-ahead of one or two characters
 *            glued to it) selects the statement; operands are
 *            whitespace-separated tokens spanning any number of lines;
 *            '#' and '%' comments only at statement level;
 *   sec. 1   every real is rounded to float32 when read;
 *   sec. 3   the statements, with one global current material that '}' and
 *            the end of an include do not restore (sec. 3.2);
 *   sec. 3.4 'xs' and 'x' blocks compose as M = X1 X2 ... Xk, X = T R S.
 *
 * Robustness: every count is checked against the bytes left before
 * anything is allocated for it (each operand takes at least two bytes),
 * and the whole load against the budgets of aff_internal.h, the bytes and
 * triangles of every inclusion counted again, before the memory for them
 * is allocated; includes are opened under the file policy of aff_file.c.
 * So a malformed or hostile file fails with "file:line: reason" in bounded
 * memory and time; a fuzz target (conformance/fuzz) runs over this file.
 */
#include "rtu/aff_internal.h"


#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOKEN_SIZE 256
#define PI 3.14159265358979323846

/* One file being read. */
struct reader {
    const char *name; /* as reported in errors: the bare file name */
    const char *text;
    size_t length, pos;
    int line;
};

/* A transform block on the block stack. */
struct block {
    int frame;          /* current frame before the block */
    double local[16];   /* static matrix relative to that frame before it */
    int local_index;
};

/* A distinct file read, identified by device and inode, and its text
 * (kept for the whole load: an include read again is not opened again). */
struct file_entry {
    uint64_t device, inode;
    const char *text;
    size_t length;
    char *owned; /* the text when read here (NULL: the caller's) */
};

/* An include name already resolved: the file it names. */
struct name_entry {
    char *name;
    int file;
};

struct parser {
    struct aff_data *data;
    char *error;
    size_t error_size;
    const char *directory; /* NULL: no includes */
    const char *root;      /* includes must lie below; NULL: anywhere */
    const struct aff_limits *limits;
    int include_depth;
    /* The budgets (aff_internal.h): distinct input, and the work of every
     * expansion. */
    uint64_t input_bytes;  /* of the distinct files read */
    uint64_t read_bytes;   /* of every file read, each inclusion counted */
    uint64_t triangles;    /* made, each inclusion counted */
    struct file_entry *files; /* distinct files read so far */
    int file_count, file_capacity;
    /* Hash tables (open addressing, -1: empty) of files by identity and of
     * include names, so that a repeated include costs its parse only (the
     * fan-out of ten thousand inclusions took seconds of system calls). */
    int *file_slots, *name_slots;
    int file_slot_count, name_slot_count;
    struct name_entry *names;
    int name_count, name_capacity;
    int detail;
    /* Current state. */
    int material;
    int frame;
    double local[16];
    int local_index; /* -1: `local` not interned yet */
    struct block *blocks;
    int block_count, block_capacity;
};

/* ------------------------------------------------------------ errors */

static int fail(struct parser *ps, const struct reader *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int fail(struct parser *ps, const struct reader *r, const char *fmt, ...)
{
    char reason[AFF_ERROR_SIZE];
    va_list args;
    va_start(args, fmt);
    vsnprintf(reason, sizeof reason, fmt, args);
    va_end(args);
    if (r)
        snprintf(ps->error, ps->error_size, "%s:%d: %s", r->name, r->line, reason);
    else
        snprintf(ps->error, ps->error_size, "%s", reason);
    return -1;
}

static int out_of_memory(struct parser *ps, const struct reader *r)
{
    return fail(ps, r, "out of memory");
}

/* Grows *array (element size `size`) to hold at least `need` elements. */
static int grow(void **array, int *capacity, int need, size_t size)
{
    if (need <= *capacity)
        return 0;
    if (need > (1 << 28))
        return -1;
    int cap = *capacity ? *capacity : 8;
    while (cap < need)
        cap *= 2;
    void *p = realloc(*array, (size_t)cap * size);
    if (!p)
        return -1;
    *array = p;
    *capacity = cap;
    return 0;
}

static int grow_u32(void **array, uint32_t *capacity, uint32_t need, size_t size)
{
    int cap = (int)*capacity;
    if (need > (1u << 28))
        return -1;
    int rc = grow(array, &cap, (int)need, size);
    *capacity = (uint32_t)cap;
    return rc;
}

static char *dup_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

/* ------------------------------------------------------------ lexing */

/* FORMAT.md sec. 1: \r \t \n \f \v and space are whitespace. */
static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

static int peek(const struct reader *r)
{
    return r->pos < r->length ? (unsigned char)r->text[r->pos] : -1;
}

static int next(struct reader *r)
{
    if (r->pos >= r->length)
        return -1;
    int c = (unsigned char)r->text[r->pos++];
    if (c == '\n')
        r->line++;
    return c;
}

static void skip_space(struct reader *r)
{
    while (r->pos < r->length && is_space((unsigned char)r->text[r->pos]))
        next(r);
}

static size_t bytes_left(const struct reader *r)
{
    return r->length - r->pos;
}

/* Reads the next whitespace-delimited token into tok. */
static int read_token(struct parser *ps, struct reader *r, char *tok, const char *what)
{
    skip_space(r);
    size_t n = 0;
    while (r->pos < r->length && !is_space((unsigned char)r->text[r->pos])) {
        if (n + 1 >= TOKEN_SIZE)
            return fail(ps, r, "%s: token longer than %d characters", what, TOKEN_SIZE - 1);
        tok[n++] = (char)next(r);
    }
    tok[n] = '\0';
    if (n == 0)
        return fail(ps, r, "unexpected end of file, expected %s", what);
    if (memchr(tok, '\0', n))
        return fail(ps, r, "NUL byte in %s", what);
    return 0;
}

/* A C decimal literal (FORMAT.md sec. 1), rounded to float32. */
static int read_real(struct parser *ps, struct reader *r, float *out, const char *what)
{
    char tok[TOKEN_SIZE];
    if (read_token(ps, r, tok, what))
        return -1;
    /* strtod would also take "nan", "inf" and hex floats: AFF has none. */
    for (const char *c = tok; *c; c++)
        if (!isdigit((unsigned char)*c) && !strchr("+-.eE", *c))
            return fail(ps, r, "%s: '%s' is not a number", what, tok);
    char *end;
    errno = 0;
    double v = strtod(tok, &end);
    if (end == tok || *end != '\0')
        return fail(ps, r, "%s: '%s' is not a number", what, tok);
    float f = (float)v;
    if (!isfinite(f))
        return fail(ps, r, "%s: %s is out of the float range", what, tok);
    *out = f;
    return 0;
}

static int read_reals(struct parser *ps, struct reader *r, float *out, int n, const char *what)
{
    for (int k = 0; k < n; k++)
        if (read_real(ps, r, &out[k], what))
            return -1;
    return 0;
}

static int read_int(struct parser *ps, struct reader *r, long lo, long hi, long *out,
                    const char *what)
{
    char tok[TOKEN_SIZE];
    if (read_token(ps, r, tok, what))
        return -1;
    char *end;
    errno = 0;
    long v = strtol(tok, &end, 10);
    if (end == tok || *end != '\0')
        return fail(ps, r, "%s: '%s' is not an integer", what, tok);
    if (errno == ERANGE || v < lo || v > hi)
        return fail(ps, r, "%s: %s is outside [%ld, %ld]", what, tok, lo, hi);
    *out = v;
    return 0;
}

/* A count of items of `per_item` operands each: bounded by what the rest
 * of the file can hold (every operand needs a character and a separator). */
static int read_count(struct parser *ps, struct reader *r, long lo, int per_item, long *out,
                      const char *what)
{
    if (read_int(ps, r, lo, 1L << 26, out, what))
        return -1;
    if ((double)*out * per_item * 2.0 > (double)bytes_left(r) + 1.0)
        return fail(ps, r, "%s: %ld items cannot fit in the rest of the file", what, *out);
    return 0;
}

static int expect_word(struct parser *ps, struct reader *r, const char *word, const char *what)
{
    char tok[TOKEN_SIZE];
    if (read_token(ps, r, tok, what))
        return -1;
    if (strcmp(tok, word) != 0)
        return fail(ps, r, "%s: expected '%s', found '%s'", what, word, tok);
    return 0;
}

/* True when the next token starts like a number (optional light colour). */
static int number_follows(struct reader *r)
{
    size_t save = r->pos;
    int line = r->line;
    skip_space(r);
    int c = peek(r);
    r->pos = save;
    r->line = line;
    return c >= 0 && (isdigit(c) || c == '-' || c == '+' || c == '.');
}

/* ------------------------------------------------------------ matrices */

/* FORMAT.md sec. 3.4: M = T R S, the axis normalised, angle in degrees
 * (sec. 4: R = cos I + sin [n]x + (1 - cos) n n^T). */
static void mat_trs(double m[16], const float s[3], const float axis[3], float degrees,
                    const float tr[3])
{
    double n[3] = {axis[0], axis[1], axis[2]};
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double a = (double)degrees * PI / 180.0;
    double r[3][3];
    if (len > 0.0 && isfinite(len)) {
        for (int k = 0; k < 3; k++)
            n[k] /= len;
    } else {
        n[0] = 1.0, n[1] = n[2] = 0.0, a = 0.0;
    }
    double c = cos(a), sn = sin(a), t = 1.0 - c;
    r[0][0] = c + t * n[0] * n[0];
    r[0][1] = t * n[0] * n[1] - sn * n[2];
    r[0][2] = t * n[0] * n[2] + sn * n[1];
    r[1][0] = t * n[1] * n[0] + sn * n[2];
    r[1][1] = c + t * n[1] * n[1];
    r[1][2] = t * n[1] * n[2] - sn * n[0];
    r[2][0] = t * n[2] * n[0] - sn * n[1];
    r[2][1] = t * n[2] * n[1] + sn * n[0];
    r[2][2] = c + t * n[2] * n[2];
    aff_matrix_identity(m);
    for (int row = 0; row < 3; row++) {
        for (int col = 0; col < 3; col++)
            m[col * 4 + row] = r[row][col] * (double)s[col];
        m[12 + row] = tr[row];
    }
}

static int intern_local(struct parser *ps, const struct reader *r)
{
    if (ps->local_index >= 0)
        return ps->local_index;
    struct aff_data *d = ps->data;
    if (grow((void **)&d->matrices, &d->matrix_capacity, d->matrix_count + 1, sizeof *d->matrices))
        return out_of_memory(ps, r);
    memcpy(d->matrices[d->matrix_count], ps->local, sizeof ps->local);
    ps->local_index = d->matrix_count++;
    return ps->local_index;
}

/* ------------------------------------------------------------ geometry */

static uint64_t read_budget(const struct parser *ps)
{
    if (ps->limits->max_read_bytes)
        return ps->limits->max_read_bytes;
    uint64_t b = AFF_READ_PER_INPUT * ps->input_bytes + AFF_READ_BASE;
    return b < AFF_READ_CAP ? b : AFF_READ_CAP;
}

static uint64_t triangle_budget(const struct parser *ps)
{
    if (ps->limits->max_triangles)
        return ps->limits->max_triangles;
    uint64_t b = ps->input_bytes / AFF_INPUT_PER_TRIANGLE + AFF_TRIANGLES_BASE;
    return b < AFF_TRIANGLES_CAP ? b : AFF_TRIANGLES_CAP;
}

/* Counts `count` more triangles against the budget, before anything is
 * allocated for them.  Tessellation is where a few bytes become many
 * triangles (a 9-byte 's' is 1024, 96 KiB): a 1 MB file of spheres once
 * reached 1.6 GB before it was refused. */
static int take_triangles(struct parser *ps, const struct reader *r, uint64_t count)
{
    uint64_t budget = triangle_budget(ps);
    if (ps->triangles + count > budget)
        return fail(ps, r,
                    "the scene makes more than %llu triangles (every inclusion counted; "
                    "the budget for %llu bytes of input, RTU_AFF_MAX_TRIANGLES raises it)",
                    (unsigned long long)budget, (unsigned long long)ps->input_bytes);
    ps->triangles += count;
    return 0;
}

static struct aff_group *current_group(struct parser *ps)
{
    return &ps->data->frames[ps->frame].group;
}

/* Opens a batch of `count` > 0 triangles; returns a pointer to them
 * (zeroed).  (With count 0 the group may have no triangle array yet, and
 * &tris[0] of a null pointer is undefined behaviour.) */
static struct aff_triangle *begin_batch(struct parser *ps, const struct reader *r, uint32_t count,
                                        int texture, int has_uv)
{
    if (take_triangles(ps, r, count))
        return NULL;
    int matrix = intern_local(ps, r);
    if (matrix < 0)
        return NULL;
    struct aff_group *g = current_group(ps);
    if (count > (1u << 26) - g->tri_count) {
        fail(ps, r, "too many triangles in one object");
        return NULL;
    }
    if (grow_u32((void **)&g->tris, &g->tri_capacity, g->tri_count + count, sizeof *g->tris) ||
        grow_u32((void **)&g->batches, &g->batch_capacity, g->batch_count + 1,
                 sizeof *g->batches)) {
        out_of_memory(ps, r);
        return NULL;
    }
    struct aff_batch *b = &g->batches[g->batch_count++];
    b->first = g->tri_count;
    b->count = count;
    b->matrix = matrix;
    b->material = ps->material;
    b->texture = texture;
    b->has_uv = has_uv;
    struct aff_triangle *t = &g->tris[g->tri_count];
    memset(t, 0, count * sizeof *t);
    g->tri_count += count;
    if (ps->frame == 0)
        ps->data->static_triangles += count;
    else
        ps->data->animated_triangles += count;
    return t;
}

static int intern_texture(struct parser *ps, const struct reader *r, const char *name)
{
    struct aff_data *d = ps->data;
    for (int i = 0; i < d->texture_count; i++)
        if (strcmp(d->textures[i].name, name) == 0)
            return i;
    if (grow((void **)&d->textures, &d->texture_capacity, d->texture_count + 1,
             sizeof *d->textures))
        return out_of_memory(ps, r);
    struct aff_texture *t = &d->textures[d->texture_count];
    memset(t, 0, sizeof *t);
    size_t n = strlen(d->directory) + strlen(name) + 2;
    t->name = dup_string(name);
    t->path = malloc(n);
    if (!t->name || !t->path) {
        free(t->name);
        free(t->path);
        return out_of_memory(ps, r);
    }
    snprintf(t->path, n, "%s%s%s", d->directory, d->directory[0] ? "/" : "", name);
    snprintf(t->where, sizeof t->where, "%.60s:%d", r->name, r->line);
    return d->texture_count++;
}

/* 'p n' / 'pp n': a convex polygon, triangulated as a fan (sec. 3.3). */
static int parse_polygon(struct parser *ps, struct reader *r, int with_normals)
{
    long n;
    int per = with_normals ? 6 : 3;
    if (read_count(ps, r, 3, per, &n, "polygon vertex count"))
        return -1;
    float *v = malloc((size_t)n * (size_t)per * sizeof(float));
    if (!v)
        return out_of_memory(ps, r);
    if (read_reals(ps, r, v, (int)(n * per), "polygon vertex")) {
        free(v);
        return -1;
    }
    struct aff_triangle *t = begin_batch(ps, r, (uint32_t)(n - 2), -1, 0);
    if (!t) {
        free(v);
        return -1;
    }
    for (long k = 1; k + 1 < n; k++, t++) {
        const long idx[3] = {0, k, k + 1};
        for (int j = 0; j < 3; j++) {
            memcpy(&t->p[3 * j], &v[idx[j] * per], 3 * sizeof(float));
            if (with_normals)
                memcpy(&t->n[3 * j], &v[idx[j] * per + 3], 3 * sizeof(float));
        }
    }
    free(v);
    return 0;
}

/* 'tt name' / 'ttp name': one textured triangle. */
static int parse_textured_triangle(struct parser *ps, struct reader *r, int with_normals)
{
    char name[TOKEN_SIZE];
    float v[24];
    int per = with_normals ? 8 : 5;
    if (read_token(ps, r, name, "texture name") || read_reals(ps, r, v, 3 * per, "vertex"))
        return -1;
    int tex = intern_texture(ps, r, name);
    if (tex < 0)
        return -1;
    struct aff_triangle *t = begin_batch(ps, r, 1, tex, 1);
    if (!t)
        return -1;
    for (int j = 0; j < 3; j++) {
        memcpy(&t->p[3 * j], &v[j * per], 3 * sizeof(float));
        if (with_normals)
            memcpy(&t->n[3 * j], &v[j * per + 3], 3 * sizeof(float));
        memcpy(&t->uv[2 * j], &v[j * per + per - 2], 2 * sizeof(float));
    }
    return 0;
}

/* Segments of tessellated quadrics ('s', 'c'): the renderer only knows
 * triangles.  32 around keeps the silhouette error of a 0.03 cylinder leg
 * below 0.5% of its radius. */
#define QUADRIC_SEGMENTS 32
#define SPHERE_RINGS 16

/* Writes quad (corners 0-1-2-3 with normals) as two triangles, (0,1,2)
 * and (0,2,3), or with `reversed` winding (0,2,1) and (0,3,2); returns
 * the triangle after them. */
static struct aff_triangle *emit_quad(struct aff_triangle *t, const float *quad[4],
                                      const float *normals[4], int reversed)
{
    static const int tri[2][2][3] = {{{0, 1, 2}, {0, 2, 3}}, {{0, 2, 1}, {0, 3, 2}}};
    for (int h = 0; h < 2; h++, t++)
        for (int j = 0; j < 3; j++) {
            memcpy(&t->p[3 * j], quad[tri[reversed][h][j]], 3 * sizeof(float));
            memcpy(&t->n[3 * j], normals[tri[reversed][h][j]], 3 * sizeof(float));
        }
    return t;
}

/* 'c': open cone or cylinder between base and apex (sec. 3.3, no caps). */
static int parse_cone(struct parser *ps, struct reader *r)
{
    float v[8];
    if (read_reals(ps, r, v, 8, "cone"))
        return -1;
    double base[3] = {v[0], v[1], v[2]}, apex[3] = {v[4], v[5], v[6]};
    double rb = v[3], ra = v[7];
    if (rb < 0.0) { /* inside-only: our surfaces are two-sided */
        rb = -rb;
        ra = -ra;
    }
    double axis[3] = {apex[0] - base[0], apex[1] - base[1], apex[2] - base[2]};
    double len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    if (!(len > 0.0) || !isfinite(len))
        return fail(ps, r, "cone: base and apex coincide");
    for (int k = 0; k < 3; k++)
        axis[k] /= len;
    /* An orthonormal frame (u, w) around the axis. */
    double pick[3] = {fabs(axis[0]) < 0.9 ? 1.0 : 0.0, fabs(axis[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    double u[3] = {axis[1] * pick[2] - axis[2] * pick[1], axis[2] * pick[0] - axis[0] * pick[2],
                   axis[0] * pick[1] - axis[1] * pick[0]};
    double ul = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int k = 0; k < 3; k++)
        u[k] /= ul;
    double w[3] = {axis[1] * u[2] - axis[2] * u[1], axis[2] * u[0] - axis[0] * u[2],
                   axis[0] * u[1] - axis[1] * u[0]};
    struct aff_triangle *t = begin_batch(ps, r, 2 * QUADRIC_SEGMENTS, -1, 0);
    if (!t)
        return -1;
    /* The normal of a cone side tilts by the slope (rb - ra) / len. */
    double slope = (rb - ra) / len;
    for (int s = 0; s < QUADRIC_SEGMENTS; s++) {
        float pb[2][3], pa[2][3], nn[2][3];
        for (int e = 0; e < 2; e++) {
            double a = 2.0 * PI * (double)(s + e) / QUADRIC_SEGMENTS;
            double dir[3], nrm[3];
            for (int k = 0; k < 3; k++) {
                dir[k] = cos(a) * u[k] + sin(a) * w[k];
                nrm[k] = dir[k] + slope * axis[k];
            }
            for (int k = 0; k < 3; k++) {
                pb[e][k] = (float)(base[k] + rb * dir[k]);
                pa[e][k] = (float)(apex[k] + ra * dir[k]);
                nn[e][k] = (float)nrm[k];
            }
        }
        const float *quad[4] = {pb[0], pb[1], pa[1], pa[0]};
        const float *qn[4] = {nn[0], nn[1], nn[1], nn[0]};
        t = emit_quad(t, quad, qn, 0);
    }
    return 0;
}

/* 's': sphere, tessellated in latitude-longitude rings. */
static int parse_sphere(struct parser *ps, struct reader *r)
{
    float v[4];
    if (read_reals(ps, r, v, 4, "sphere"))
        return -1;
    double rad = fabs((double)v[3]);
    if (!(rad > 0.0))
        return fail(ps, r, "sphere: radius is zero");
    struct aff_triangle *t = begin_batch(ps, r, 2 * QUADRIC_SEGMENTS * SPHERE_RINGS, -1, 0);
    if (!t)
        return -1;
    /* The corners share their angles: sin and cos of each once, 100 calls
     * instead of 8192 per sphere, the same values (the trigonometry was
     * half the fuzz target's time). */
    double sin_theta[SPHERE_RINGS + 1], cos_theta[SPHERE_RINGS + 1];
    double sin_phi[QUADRIC_SEGMENTS + 1], cos_phi[QUADRIC_SEGMENTS + 1];
    for (int i = 0; i <= SPHERE_RINGS; i++) {
        double theta = PI * (double)i / SPHERE_RINGS;
        sin_theta[i] = sin(theta);
        cos_theta[i] = cos(theta);
    }
    for (int i = 0; i <= QUADRIC_SEGMENTS; i++) {
        double phi = 2.0 * PI * (double)i / QUADRIC_SEGMENTS;
        sin_phi[i] = sin(phi);
        cos_phi[i] = cos(phi);
    }
    for (int ring = 0; ring < SPHERE_RINGS; ring++)
        for (int s = 0; s < QUADRIC_SEGMENTS; s++) {
            float p[4][3], n[4][3];
            for (int c = 0; c < 4; c++) {
                int i = ring + (c >> 1), j = s + ((c ^ (c >> 1)) & 1);
                double d[3] = {sin_theta[i] * cos_phi[j], cos_theta[i], sin_theta[i] * sin_phi[j]};
                for (int k = 0; k < 3; k++) {
                    n[c][k] = (float)d[k];
                    p[c][k] = (float)((double)v[k] + rad * d[k]);
                }
            }
            const float *quad[4] = {p[0], p[1], p[2], p[3]};
            const float *qn[4] = {n[0], n[1], n[2], n[3]};
            t = emit_quad(t, quad, qn, 1);
        }
    return 0;
}

/* 'm': indexed mesh (sec. 3.3): vertices, [normals], [texturecoords
 * name], triangles, rows of 3, 6 or 9 0-based indices. */
static int parse_mesh(struct parser *ps, struct reader *r)
{
    long nv, nn = 0, nt = 0, ntri;
    float *pos = NULL, *nrm = NULL, *uv = NULL;
    int tex = -1, rc = -1;
    char tok[TOKEN_SIZE];
    if (expect_word(ps, r, "vertices", "mesh") || read_count(ps, r, 0, 3, &nv, "vertex count"))
        return -1;
    pos = malloc((size_t)(nv ? nv : 1) * 3 * sizeof(float));
    if (!pos)
        return out_of_memory(ps, r);
    if (read_reals(ps, r, pos, (int)nv * 3, "mesh vertex") ||
        read_token(ps, r, tok, "'normals', 'texturecoords' or 'triangles'"))
        goto done;
    if (strcmp(tok, "normals") == 0) {
        if (read_count(ps, r, 0, 3, &nn, "normal count"))
            goto done;
        nrm = malloc((size_t)(nn ? nn : 1) * 3 * sizeof(float));
        if (!nrm) {
            out_of_memory(ps, r);
            goto done;
        }
        if (read_reals(ps, r, nrm, (int)nn * 3, "mesh normal") ||
            read_token(ps, r, tok, "'texturecoords' or 'triangles'"))
            goto done;
    }
    if (strcmp(tok, "texturecoords") == 0) {
        char name[TOKEN_SIZE];
        if (read_count(ps, r, 0, 2, &nt, "texture coordinate count") ||
            read_token(ps, r, name, "texture name"))
            goto done;
        if ((tex = intern_texture(ps, r, name)) < 0)
            goto done;
        uv = malloc((size_t)(nt ? nt : 1) * 2 * sizeof(float));
        if (!uv) {
            out_of_memory(ps, r);
            goto done;
        }
        if (read_reals(ps, r, uv, (int)nt * 2, "texture coordinate") ||
            read_token(ps, r, tok, "'triangles'"))
            goto done;
    }
    if (strcmp(tok, "triangles") != 0) {
        fail(ps, r, "mesh: expected 'triangles', found '%s'", tok);
        goto done;
    }
    int per = 3 + (nrm ? 3 : 0) + (uv ? 3 : 0);
    if (read_count(ps, r, 0, per, &ntri, "triangle count"))
        goto done;
    /* 'triangles 0' is a mesh of nothing: no batch (begin_batch needs at
     * least one triangle; found by conformance/fuzz). */
    if (ntri == 0) {
        rc = 0;
        goto done;
    }
    struct aff_triangle *t = begin_batch(ps, r, (uint32_t)ntri, tex, uv != NULL);
    if (!t)
        goto done;
    for (long i = 0; i < ntri; i++, t++) {
        long idx[9];
        for (int j = 0; j < per; j++) {
            long limit = j < 3 ? nv : (j < 6 && nrm) ? nn : nt;
            if (read_int(ps, r, 0, limit - 1, &idx[j], "mesh triangle index")) {
                if (limit == 0)
                    fail(ps, r, "mesh triangle %ld refers to an empty list", i);
                goto done;
            }
        }
        for (int j = 0; j < 3; j++) {
            memcpy(&t->p[3 * j], &pos[3 * idx[j]], 3 * sizeof(float));
            if (nrm)
                memcpy(&t->n[3 * j], &nrm[3 * idx[3 + j]], 3 * sizeof(float));
            if (uv)
                memcpy(&t->uv[2 * j], &uv[2 * idx[(nrm ? 6 : 3) + j]], 2 * sizeof(float));
        }
    }
    rc = 0;
done:
    free(pos);
    free(nrm);
    free(uv);
    return rc;
}

/* 'tpa n' + n x (time, 3 x (x y z nx ny nz)) (sec. 3.3, 7.5).  The keys
 * are transformed by the current static matrix now, which commutes with
 * the linear interpolation of sec. 7.5. */
static int parse_tpa(struct parser *ps, struct reader *r)
{
    long n;
    if (read_count(ps, r, 1, 19, &n, "tpa key count") || take_triangles(ps, r, 1))
        return -1;
    struct aff_tpa_key *keys = malloc((size_t)n * sizeof *keys);
    if (!keys)
        return out_of_memory(ps, r);
    /* Normals go through the cofactor (inverse transpose up to a scale). */
    const double *m = ps->local;
    double c[9];
    c[0] = m[5] * m[10] - m[6] * m[9];
    c[1] = m[6] * m[8] - m[4] * m[10];
    c[2] = m[4] * m[9] - m[5] * m[8];
    c[3] = m[9] * m[2] - m[10] * m[1];
    c[4] = m[10] * m[0] - m[8] * m[2];
    c[5] = m[8] * m[1] - m[9] * m[0];
    c[6] = m[1] * m[6] - m[2] * m[5];
    c[7] = m[2] * m[4] - m[0] * m[6];
    c[8] = m[0] * m[5] - m[1] * m[4];
    for (long k = 0; k < n; k++) {
        float v[19];
        if (read_reals(ps, r, v, 19, "tpa key")) {
            free(keys);
            return -1;
        }
        keys[k].time = v[0];
        for (int j = 0; j < 3; j++) {
            const float *p = &v[1 + 6 * j], *nn = &v[4 + 6 * j];
            for (int row = 0; row < 3; row++) {
                keys[k].p[3 * j + row] = (float)(m[row] * p[0] + m[4 + row] * p[1] +
                                                 m[8 + row] * p[2] + m[12 + row]);
                keys[k].n[3 * j + row] =
                    (float)(c[3 * row] * nn[0] + c[3 * row + 1] * nn[1] + c[3 * row + 2] * nn[2]);
            }
        }
    }
    struct aff_group *g = current_group(ps);
    if (grow_u32((void **)&g->tpas, &g->tpa_capacity, g->tpa_count + 1, sizeof *g->tpas)) {
        free(keys);
        return out_of_memory(ps, r);
    }
    g->tpas[g->tpa_count].key_count = (int)n;
    g->tpas[g->tpa_count].keys = keys;
    g->tpas[g->tpa_count].material = ps->material;
    g->tpa_count++;
    ps->data->tpa_triangles++;
    return 0;
}

/* ------------------------------------------------------------ state */

static int add_material(struct parser *ps, const struct reader *r, const struct aff_material *m)
{
    struct aff_data *d = ps->data;
    if (d->material_count >= 65535)
        return fail(ps, r, "more than 65535 materials");
    if (grow((void **)&d->materials, &d->material_capacity, d->material_count + 1,
             sizeof *d->materials))
        return out_of_memory(ps, r);
    d->materials[d->material_count] = *m;
    ps->material = d->material_count++;
    return 0;
}

static int push_block(struct parser *ps, const struct reader *r)
{
    if (ps->block_count >= AFF_MAX_BLOCK_DEPTH)
        return fail(ps, r, "transform blocks nested deeper than %d", AFF_MAX_BLOCK_DEPTH);
    if (grow((void **)&ps->blocks, &ps->block_capacity, ps->block_count + 1, sizeof *ps->blocks))
        return out_of_memory(ps, r);
    struct block *b = &ps->blocks[ps->block_count++];
    b->frame = ps->frame;
    memcpy(b->local, ps->local, sizeof b->local);
    b->local_index = ps->local_index;
    return 0;
}

static int expect_open_brace(struct parser *ps, struct reader *r, const char *what)
{
    skip_space(r);
    if (next(r) != '{')
        return fail(ps, r, "%s: expected '{'", what);
    return 0;
}

/* 'xs sx sy sz ax ay az deg tx ty tz {' */
static int parse_static_transform(struct parser *ps, struct reader *r)
{
    float v[10];
    if (read_reals(ps, r, v, 10, "xs") || expect_open_brace(ps, r, "xs") || push_block(ps, r))
        return -1;
    double m[16];
    mat_trs(m, &v[0], &v[3], v[6], &v[7]);
    aff_matrix_mul(ps->local, ps->local, m);
    ps->local_index = -1;
    return 0;
}

/* 'x name {' : a new frame under the current one. */
static int parse_animated_transform(struct parser *ps, struct reader *r)
{
    char name[TOKEN_SIZE];
    if (read_token(ps, r, name, "transform name") || expect_open_brace(ps, r, "x"))
        return -1;
    struct aff_data *d = ps->data;
    int matrix = intern_local(ps, r);
    if (matrix < 0 || push_block(ps, r))
        return -1;
    if (grow((void **)&d->frames, &d->frame_capacity, d->frame_count_nodes + 1, sizeof *d->frames))
        return out_of_memory(ps, r);
    struct aff_frame *f = &d->frames[d->frame_count_nodes];
    memset(f, 0, sizeof *f);
    f->parent = ps->frame;
    f->matrix = matrix;
    f->animation = -1;
    if (!(f->name = dup_string(name)))
        return out_of_memory(ps, r);
    ps->frame = d->frame_count_nodes++;
    aff_matrix_identity(ps->local);
    ps->local_index = -1;
    return 0;
}

static int close_block(struct parser *ps, const struct reader *r)
{
    if (ps->block_count == 0)
        return fail(ps, r, "'}' without an open transform block");
    struct block *b = &ps->blocks[--ps->block_count];
    ps->frame = b->frame;
    memcpy(ps->local, b->local, sizeof ps->local);
    ps->local_index = b->local_index;
    return 0;
}

/* ------------------------------------------------------------ keyframes */

static int parse_spline_track(struct parser *ps, struct reader *r, struct aff_track *track,
                              int kind, const char *what)
{
    long n;
    int values = kind == AFF_TRACK_ROT ? 4 : 3;
    if (read_count(ps, r, 0, 4 + values, &n, what))
        return -1;
    if (n < 4)
        return fail(ps, r, "%s: %ld keys, at least 4 are needed (FORMAT.md sec. 7.1)", what, n);
    struct aff_key *keys = malloc((size_t)n * sizeof *keys);
    if (!keys)
        return out_of_memory(ps, r);
    for (long k = 0; k < n; k++) {
        float v[8];
        if (read_reals(ps, r, v, 4 + values, what)) {
            free(keys);
            return -1;
        }
        keys[k].time = v[0];
        for (int j = 0; j < 4; j++)
            keys[k].v[j] = j < values ? v[1 + j] : 0.0;
        keys[k].tension = v[1 + values];
        keys[k].continuity = v[2 + values];
        keys[k].bias = v[3 + values];
    }
    if (aff_track_init(track, kind, keys, (int)n))
        return out_of_memory(ps, r);
    return 0;
}

static void animation_release(struct aff_animation *a)
{
    free(a->name);
    if (a->has_transl)
        aff_track_release(&a->transl);
    if (a->has_rot)
        aff_track_release(&a->rot);
    if (a->has_scale)
        aff_track_release(&a->scale);
    free(a->visibility.times);
    free(a->visibility.flags);
    memset(a, 0, sizeof *a);
}

/* 'k name { transl n ... rot n ... scale n ... visibility n ... }' */
static int parse_keyframes(struct parser *ps, struct reader *r)
{
    char name[TOKEN_SIZE], tok[TOKEN_SIZE];
    struct aff_animation a;
    memset(&a, 0, sizeof a);
    if (read_token(ps, r, name, "keyframe name") || expect_open_brace(ps, r, "k"))
        return -1;
    for (;;) {
        skip_space(r);
        if (peek(r) == '}') {
            next(r);
            break;
        }
        if (read_token(ps, r, tok, "track name or '}'"))
            goto fail_anim;
        int *has = NULL;
        struct aff_track *track = NULL;
        int kind = 0;
        if (strcmp(tok, "transl") == 0)
            has = &a.has_transl, track = &a.transl, kind = AFF_TRACK_TRANSL;
        else if (strcmp(tok, "rot") == 0)
            has = &a.has_rot, track = &a.rot, kind = AFF_TRACK_ROT;
        else if (strcmp(tok, "scale") == 0)
            has = &a.has_scale, track = &a.scale, kind = AFF_TRACK_SCALE;
        else if (strcmp(tok, "visibility") == 0)
            has = &a.has_visibility;
        else {
            fail(ps, r, "k %s: unknown track '%s'", name, tok);
            goto fail_anim;
        }
        if (*has) {
            fail(ps, r, "k %s: track '%s' given twice", name, tok);
            goto fail_anim;
        }
        if (track) {
            if (parse_spline_track(ps, r, track, kind, tok))
                goto fail_anim;
        } else {
            long n;
            if (read_count(ps, r, 0, 2, &n, "visibility key count"))
                goto fail_anim;
            a.visibility.times = malloc((size_t)(n ? n : 1) * sizeof(double));
            a.visibility.flags = malloc((size_t)(n ? n : 1) * sizeof(int));
            if (!a.visibility.times || !a.visibility.flags) {
                free(a.visibility.times);
                free(a.visibility.flags);
                a.visibility.times = NULL;
                a.visibility.flags = NULL;
                out_of_memory(ps, r);
                goto fail_anim;
            }
            /* Set now so animation_release frees the arrays on failure. */
            *has = 1;
            for (long k = 0; k < n; k++) {
                float time;
                long flag;
                if (read_real(ps, r, &time, "visibility time") ||
                    read_int(ps, r, 0, 1, &flag, "visibility flag"))
                    goto fail_anim;
                a.visibility.times[k] = time;
                a.visibility.flags[k] = (int)flag;
            }
            a.visibility.key_count = (int)n;
        }
        *has = 1;
    }
    if (!(a.name = dup_string(name))) {
        out_of_memory(ps, r);
        goto fail_anim;
    }
    /* A later definition of a name replaces the earlier (sec. 3.4). */
    struct aff_data *d = ps->data;
    for (int i = 0; i < d->animation_count; i++)
        if (strcmp(d->animations[i].name, name) == 0) {
            animation_release(&d->animations[i]);
            d->animations[i] = a;
            return 0;
        }
    if (grow((void **)&d->animations, &d->animation_capacity, d->animation_count + 1,
             sizeof *d->animations)) {
        out_of_memory(ps, r);
        goto fail_anim;
    }
    d->animations[d->animation_count++] = a;
    return 0;
fail_anim:
    animation_release(&a);
    return -1;
}

/* ------------------------------------------------------------ statements */

static int parse_view(struct parser *ps, struct reader *r)
{
    struct aff_data *d = ps->data;
    long res[2];
    if (expect_word(ps, r, "from", "view") || read_reals(ps, r, d->from, 3, "from") ||
        expect_word(ps, r, "at", "view") || read_reals(ps, r, d->at, 3, "at") ||
        expect_word(ps, r, "up", "view") || read_reals(ps, r, d->up, 3, "up") ||
        expect_word(ps, r, "angle", "view") || read_real(ps, r, &d->fov_degrees, "angle") ||
        expect_word(ps, r, "hither", "view") || read_real(ps, r, &d->hither, "hither") ||
        expect_word(ps, r, "resolution", "view") ||
        read_int(ps, r, 1, 16384, &res[0], "x resolution") ||
        read_int(ps, r, 1, 16384, &res[1], "y resolution"))
        return -1;
    if (!(d->fov_degrees > 0.0f && d->fov_degrees < 180.0f))
        return fail(ps, r, "view: angle %g is outside (0, 180)", (double)d->fov_degrees);
    /* FORMAT.md sec. 3.1: the reference replaces hither < 0.0001 by 1. */
    if (d->hither < 0.0001f)
        d->hither = 1.0f;
    d->resolution[0] = (int)res[0];
    d->resolution[1] = (int)res[1];
    d->has_view = 1;
    return 0;
}

static int parse_light(struct parser *ps, struct reader *r, int named)
{
    struct aff_light l;
    char name[TOKEN_SIZE];
    memset(&l, 0, sizeof l);
    l.animation = -1;
    l.color[0] = l.color[1] = l.color[2] = 1.0f;
    if (named && read_token(ps, r, name, "light name"))
        return -1;
    if (read_reals(ps, r, l.position, 3, "light position"))
        return -1;
    if (number_follows(r) && read_reals(ps, r, l.color, 3, "light colour"))
        return -1;
    struct aff_data *d = ps->data;
    if (grow((void **)&d->lights, &d->light_capacity, d->light_count + 1, sizeof *d->lights))
        return out_of_memory(ps, r);
    if (named && !(l.name = dup_string(name)))
        return out_of_memory(ps, r);
    d->lights[d->light_count++] = l;
    return 0;
}

static int parse_reader(struct parser *ps, struct reader *r);

static uint64_t hash_bytes(const void *data, size_t n, uint64_t h)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++)
        h = (h ^ p[i]) * 1099511628211u; /* FNV-1a */
    return h;
}

static uint64_t file_hash(uint64_t device, uint64_t inode)
{
    uint64_t h = hash_bytes(&device, sizeof device, 14695981039346656037u);
    return hash_bytes(&inode, sizeof inode, h);
}

static uint64_t name_hash(const char *name)
{
    return hash_bytes(name, strlen(name), 14695981039346656037u);
}

/* Slot of the entry `key` matches in table, or of the empty slot where it
 * would go. */
static int find_file_slot(const struct parser *ps, uint64_t device, uint64_t inode)
{
    int mask = ps->file_slot_count - 1;
    for (int k = (int)(file_hash(device, inode) & (uint64_t)mask);; k = (k + 1) & mask) {
        int e = ps->file_slots[k];
        if (e < 0 || (ps->files[e].device == device && ps->files[e].inode == inode))
            return k;
    }
}

static int find_name_slot(const struct parser *ps, const char *name)
{
    int mask = ps->name_slot_count - 1;
    for (int k = (int)(name_hash(name) & (uint64_t)mask);; k = (k + 1) & mask) {
        int e = ps->name_slots[k];
        if (e < 0 || strcmp(ps->names[e].name, name) == 0)
            return k;
    }
}

/* Keeps a table at most half full for `count` entries; rehashes. */
static int reserve_slots(struct parser *ps, int **slots, int *slot_count, int count, int names)
{
    if (2 * count < *slot_count)
        return 0;
    if (count > (1 << 26))
        return -1;
    int n = *slot_count ? 2 * *slot_count : 64;
    while (2 * count >= n)
        n *= 2;
    int *fresh = malloc((size_t)n * sizeof *fresh);
    if (!fresh)
        return -1;
    for (int k = 0; k < n; k++)
        fresh[k] = -1;
    int *old = *slots;
    int old_count = *slot_count;
    *slots = fresh;
    *slot_count = n;
    for (int k = 0; k < old_count; k++)
        if (old[k] >= 0) {
            int e = old[k];
            int at = names ? find_name_slot(ps, ps->names[e].name)
                           : find_file_slot(ps, ps->files[e].device, ps->files[e].inode);
            fresh[at] = e;
        }
    free(old);
    return 0;
}

/* The distinct file with f's identity, added (its size to the input) when
 * new; -1 when memory ran out.  *added tells which. */
static int intern_file(struct parser *ps, const struct aff_file *f, int *added)
{
    *added = 0;
    if (reserve_slots(ps, &ps->file_slots, &ps->file_slot_count, ps->file_count + 1, 0) ||
        grow((void **)&ps->files, &ps->file_capacity, ps->file_count + 1, sizeof *ps->files))
        return -1;
    int slot = find_file_slot(ps, f->device, f->inode);
    if (ps->file_slots[slot] >= 0)
        return ps->file_slots[slot];
    struct file_entry *e = &ps->files[ps->file_count];
    memset(e, 0, sizeof *e);
    e->device = f->device;
    e->inode = f->inode;
    ps->file_slots[slot] = ps->file_count;
    ps->input_bytes += f->size;
    *added = 1;
    return ps->file_count++;
}

/* Counts one more reading of `size` bytes against the read budget. */
static int take_read(struct parser *ps, const struct reader *r, uint64_t size, const char *name)
{
    uint64_t budget = read_budget(ps);
    if (ps->read_bytes + size > budget)
        return fail(ps, r,
                    "include '%s': the scene reads more than %llu bytes (every inclusion "
                    "counted; the budget for %llu bytes of input, RTU_AFF_MAX_READ_MIB "
                    "raises it)",
                    name, (unsigned long long)budget, (unsigned long long)ps->input_bytes);
    ps->read_bytes += size;
    return 0;
}

/* The text of include `name`: from the names already resolved, else
 * opened under the file policy (aff_file.c) and counted as input when it
 * is a file not read before.  Returns the file's index, or -1 after
 * recording the failure. */
static int include_file(struct parser *ps, const struct reader *r, const char *name)
{
    if (reserve_slots(ps, &ps->name_slots, &ps->name_slot_count, ps->name_count + 1, 1) ||
        grow((void **)&ps->names, &ps->name_capacity, ps->name_count + 1, sizeof *ps->names))
        return out_of_memory(ps, r);
    int slot = find_name_slot(ps, name);
    if (ps->name_slots[slot] >= 0)
        return ps->names[ps->name_slots[slot]].file;
    struct aff_file f = {-1, 0, UINT64_MAX, 0};
    const char *text = NULL;
    char *owned = NULL;
    size_t len = 0;
    if (ps->limits->include_text) {
        if (ps->limits->include_text(ps->limits->include_user, name, &text, &len, &f.inode))
            return fail(ps, r, "include '%s': no such file", name);
        f.size = len;
    } else {
        size_t n = strlen(ps->directory) + strlen(name) + 2;
        char *path = malloc(n);
        if (!path)
            return out_of_memory(ps, r);
        snprintf(path, n, "%s%s%s", ps->directory, ps->directory[0] ? "/" : "", name);
        char why[AFF_ERROR_SIZE];
        int rc = aff_file_open(path, ps->root, ps->limits->max_file_bytes, &f, why, sizeof why);
        free(path);
        if (rc)
            return fail(ps, r, "include '%s': %s", name, why);
    }
    char *name_copy = dup_string(name);
    int added;
    int file = name_copy ? intern_file(ps, &f, &added) : -1;
    if (file < 0) {
        free(name_copy);
        aff_file_close(&f);
        return out_of_memory(ps, r);
    }
    if (added && !text) {
        /* Checked against the budget before it is read. */
        if (ps->read_bytes + f.size > read_budget(ps)) {
            free(name_copy);
            aff_file_close(&f);
            take_read(ps, r, f.size, name);
            return -1;
        }
        int oom;
        owned = aff_file_read(&f, &len, &oom);
        if (!owned) {
            free(name_copy);
            aff_file_close(&f);
            return oom ? out_of_memory(ps, r) : fail(ps, r, "include '%s': read error", name);
        }
        text = owned;
    }
    aff_file_close(&f);
    if (added) {
        ps->files[file].text = text;
        ps->files[file].length = len;
        ps->files[file].owned = owned;
    }
    ps->names[ps->name_count].name = name_copy;
    ps->names[ps->name_count].file = file;
    ps->name_slots[slot] = ps->name_count++;
    return file;
}

/* 'i detail file': read the file as if inserted here (sec. 3.1). */
static int parse_include(struct parser *ps, struct reader *r)
{
    long detail;
    char name[TOKEN_SIZE];
    if (read_int(ps, r, -1000000, 1000000, &detail, "include detail") ||
        read_token(ps, r, name, "include file name"))
        return -1;
    if (detail > ps->detail)
        return 0;
    if (!ps->directory && !ps->limits->include_text)
        return fail(ps, r, "include '%s': includes are not available here", name);
    if (ps->include_depth >= AFF_MAX_INCLUDE_DEPTH)
        return fail(ps, r, "include '%s': nested deeper than %d files (a cycle?)", name,
                    AFF_MAX_INCLUDE_DEPTH);
    int file = include_file(ps, r, name);
    if (file < 0)
        return -1;
    const struct file_entry *e = &ps->files[file];
    if (take_read(ps, r, e->length, name))
        return -1;
    struct reader sub = {name, e->text, e->length, 0, 1};
    ps->include_depth++;
    int rc = parse_reader(ps, &sub);
    ps->include_depth--;
    return rc;
}

/* One statement; c is its first character. */
static int parse_statement(struct parser *ps, struct reader *r, int c)
{
    struct aff_data *d = ps->data;
    int c2 = peek(r);
    switch (c) {
    case '#':
    case '%':
        while ((c = next(r)) >= 0 && c != '\n')
            ;
        return 0;
    case 'v':
        return parse_view(ps, r);
    case 'b':
        if (read_reals(ps, r, d->background, 3, "background"))
            return -1;
        d->has_background = 1;
        return 0;
    case 'a':
        if (c2 == 'm') {
            next(r);
            if (read_reals(ps, r, d->ambient, 3, "ambient"))
                return -1;
            d->has_ambient = 1;
            return 0;
        } else {
            long frames;
            if (read_real(ps, r, &d->t0, "start time") || read_real(ps, r, &d->t1, "end time") ||
                read_int(ps, r, 1, 100000000, &frames, "frame count"))
                return -1;
            d->frame_count = (int)frames;
            d->has_animation_range = 1;
            return 0;
        }
    case 'l':
        if (c2 == 'a') {
            next(r);
            return parse_light(ps, r, 1);
        }
        return parse_light(ps, r, 0);
    case 'f':
        if (c2 == 'm') {
            float v[12];
            struct aff_material m;
            next(r);
            if (read_reals(ps, r, v, 12, "material"))
                return -1;
            memcpy(m.ambient, &v[0], sizeof m.ambient);
            memcpy(m.diffuse, &v[3], sizeof m.diffuse);
            memcpy(m.specular, &v[6], sizeof m.specular);
            m.shine = v[9];
            m.transmittance = v[10];
            m.ior = v[11];
            return add_material(ps, r, &m);
        } else {
            /* NFF 'f r g b Kd Ks shine T ior' (sec. 3.2). */
            float v[8];
            struct aff_material m;
            if (read_reals(ps, r, v, 8, "material"))
                return -1;
            for (int k = 0; k < 3; k++) {
                m.ambient[k] = 0.0f;
                m.diffuse[k] = v[3] * v[k];
                m.specular[k] = v[4];
            }
            m.shine = v[5];
            m.transmittance = v[6];
            m.ior = v[7];
            return add_material(ps, r, &m);
        }
    case 'i':
        return parse_include(ps, r);
    case 'd': {
        long level;
        if (read_int(ps, r, -1000000, 1000000, &level, "detail level"))
            return -1;
        ps->detail = (int)level;
        return 0;
    }
    case 'x':
        if (c2 == 's') {
            next(r);
            return parse_static_transform(ps, r);
        }
        return parse_animated_transform(ps, r);
    case '}':
        return close_block(ps, r);
    case 'k':
        return parse_keyframes(ps, r);
    case 'm':
        return parse_mesh(ps, r);
    case 'p':
        if (c2 == 'p') {
            next(r);
            return parse_polygon(ps, r, 1);
        }
        return parse_polygon(ps, r, 0);
    case 't':
        if (c2 == 't') {
            next(r);
            if (peek(r) == 'p') {
                next(r);
                return parse_textured_triangle(ps, r, 1);
            }
            return parse_textured_triangle(ps, r, 0);
        }
        if (c2 == 'p') {
            next(r);
            if (peek(r) == 'a') {
                next(r);
                return parse_tpa(ps, r);
            }
        }
        return fail(ps, r, "unknown statement starting with 't'");
    case 's':
        return parse_sphere(ps, r);
    case 'c':
        return parse_cone(ps, r);
    default:
        if (c >= 32 && c < 127)
            return fail(ps, r, "unknown statement '%c'", c);
        return fail(ps, r, "unknown statement (byte 0x%02x)", (unsigned)c);
    }
}

static int parse_reader(struct parser *ps, struct reader *r)
{
    /* FORMAT.md sec. 3.4: braces balance within every file; a block left
     * open at the end of an include would silently capture the includer's
     * geometry, so it is an error. */
    int blocks_at_start = ps->block_count;
    for (;;) {
        skip_space(r);
        int c = next(r);
        if (c < 0)
            break;
        if (parse_statement(ps, r, c))
            return -1;
        if (ps->block_count < blocks_at_start)
            return fail(ps, r, "'}' closes a block opened in another file");
    }
    if (ps->block_count != blocks_at_start)
        return fail(ps, r, "end of file inside a transform block (missing '}')");
    return 0;
}

/* ------------------------------------------------------------ finishing */

/* Binds 'x' names and 'la' lights to 'k' blocks (which may come after
 * them, in any file) and applies the defaults of sec. 3.1. */
static void resolve(struct aff_data *d)
{
    for (int f = 1; f < d->frame_count_nodes; f++)
        for (int a = 0; a < d->animation_count; a++)
            if (strcmp(d->frames[f].name, d->animations[a].name) == 0)
                d->frames[f].animation = a;
    for (int l = 0; l < d->light_count; l++)
        if (d->lights[l].name)
            for (int a = 0; a < d->animation_count; a++)
                if (strcmp(d->lights[l].name, d->animations[a].name) == 0 &&
                    d->animations[a].has_transl)
                    d->lights[l].animation = a;
    d->camera = -1;
    for (int a = 0; a < d->animation_count; a++)
        if (strcmp(d->animations[a].name, "camera") == 0)
            d->camera = a;
    if (!d->has_ambient)
        d->ambient[0] = d->ambient[1] = d->ambient[2] = 1.0f;
    if (!d->has_animation_range) {
        d->t0 = d->t1 = 0.0f;
        d->frame_count = 1;
    }
    if (!d->has_view) {
        /* No 'v': look down -z from +z, 45 degrees, 640x480. */
        float from[3] = {0, 0, 10}, up[3] = {0, 1, 0};
        memcpy(d->from, from, sizeof from);
        memset(d->at, 0, sizeof d->at);
        memcpy(d->up, up, sizeof up);
        d->fov_degrees = 45.0f;
        d->hither = 0.01f;
        d->resolution[0] = 640;
        d->resolution[1] = 480;
    }
}

void aff_data_release(struct aff_data *d)
{
    free(d->directory);
    free(d->root);
    free(d->materials);
    for (int i = 0; i < d->texture_count; i++) {
        free(d->textures[i].name);
        free(d->textures[i].path);
    }
    free(d->textures);
    free(d->matrices);
    for (int f = 0; f < d->frame_count_nodes; f++) {
        struct aff_group *g = &d->frames[f].group;
        free(d->frames[f].name);
        free(g->tris);
        free(g->batches);
        for (uint32_t k = 0; k < g->tpa_count; k++)
            free(g->tpas[k].keys);
        free(g->tpas);
    }
    free(d->frames);
    for (int a = 0; a < d->animation_count; a++)
        animation_release(&d->animations[a]);
    free(d->animations);
    for (int l = 0; l < d->light_count; l++)
        free(d->lights[l].name);
    free(d->lights);
    memset(d, 0, sizeof *d);
}

/* aff_parse_text with the identity of the top file (NULL: a text in
 * memory), which counts once among the distinct files. */
static int parse_top(const char *name, const char *text, size_t length, const char *directory,
                     const struct aff_limits *limits, const struct aff_file *top,
                     struct aff_data *data, char *error, size_t error_size)
{
    struct parser ps;
    struct aff_limits defaults;
    if (!limits) {
        aff_limits_default(&defaults);
        limits = &defaults;
    }
    memset(&ps, 0, sizeof ps);
    memset(data, 0, sizeof *data);
    ps.data = data;
    ps.error = error;
    ps.error_size = error_size;
    ps.directory = directory;
    ps.limits = limits;
    ps.material = -1;
    aff_matrix_identity(ps.local);
    ps.local_index = -1;
    if (error_size)
        error[0] = '\0';
    data->max_file_bytes = limits->max_file_bytes;
    data->directory = dup_string(directory ? directory : "");
    data->frames = calloc(1, sizeof *data->frames);
    if (!data->directory || !data->frames) {
        aff_data_release(data);
        return fail(&ps, NULL, "%s:0: out of memory", name);
    }
    /* Includes and textures stay inside the top file's tree (with no
     * directory: textures inside the current one). */
    if (!limits->any_directory) {
        data->root = aff_file_root(data->directory);
        if (!data->root) {
            int e = errno;
            aff_data_release(data);
            return fail(&ps, NULL, "%s:0: directory '%s': %s", name,
                        directory && directory[0] ? directory : ".",
                        e == ENOMEM ? "out of memory" : strerror(e));
        }
        ps.root = data->root;
    }
    data->frames[0].parent = -1;
    data->frames[0].animation = -1;
    data->frame_count_nodes = data->frame_capacity = 1;
    struct reader r = {name, text, length, 0, 1};
    int rc = 0;
    ps.read_bytes = length;
    if (top) {
        /* Identified like an include, so including it again is no new
         * input; its text is the caller's. */
        struct aff_file f = *top;
        int added;
        f.size = length;
        int file = intern_file(&ps, &f, &added);
        if (file < 0) {
            rc = fail(&ps, NULL, "%s:0: out of memory", name);
        } else {
            ps.files[file].text = text;
            ps.files[file].length = length;
        }
    } else {
        ps.input_bytes = length;
    }
    if (rc == 0 && ps.read_bytes > read_budget(&ps))
        rc = fail(&ps, NULL, "%s:0: %llu bytes, more than the read budget of %llu", name,
                  (unsigned long long)length, (unsigned long long)read_budget(&ps));
    if (rc == 0)
        rc = parse_reader(&ps, &r);
    free(ps.blocks);
    for (int i = 0; i < ps.file_count; i++)
        free(ps.files[i].owned);
    free(ps.files);
    for (int i = 0; i < ps.name_count; i++)
        free(ps.names[i].name);
    free(ps.names);
    free(ps.file_slots);
    free(ps.name_slots);
    if (rc) {
        aff_data_release(data);
        return -1;
    }
    resolve(data);
    return 0;
}

int aff_parse_text(const char *name, const char *text, size_t length, const char *directory,
                   const struct aff_limits *limits, struct aff_data *data, char *error,
                   size_t error_size)
{
    return parse_top(name, text, length, directory, limits, NULL, data, error, error_size);
}

int aff_parse_file(const char *path, const struct aff_limits *limits, struct aff_data *data,
                   char *error, size_t error_size)
{
    struct aff_limits defaults;
    if (!limits) {
        aff_limits_default(&defaults);
        limits = &defaults;
    }
    memset(data, 0, sizeof *data);
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    size_t dir_len = slash ? (size_t)(slash - path) : 0;
    char *dir = malloc(dir_len + 2);
    if (!dir) {
        snprintf(error, error_size, "%s:0: out of memory", path);
        return -1;
    }
    if (slash && dir_len == 0) /* "/scene.aff" */
        memcpy(dir, "/", 2);
    else {
        memcpy(dir, path, dir_len);
        dir[dir_len] = '\0';
    }
    /* The top file is the caller's choice (no directory rule), but it is
     * opened like an include: a regular file within the size limit. */
    struct aff_file f;
    char why[AFF_ERROR_SIZE];
    if (aff_file_open(path, NULL, limits->max_file_bytes, &f, why, sizeof why)) {
        snprintf(error, error_size, "%s:0: %s", path, why);
        free(dir);
        return -1;
    }
    size_t len = 0;
    int oom;
    char *text = aff_file_read(&f, &len, &oom);
    aff_file_close(&f);
    int rc;
    if (!text) {
        snprintf(error, error_size, "%s:0: %s", path, oom ? "out of memory" : "read error");
        rc = -1;
    } else {
        f.size = len;
        rc = parse_top(base, text, len, dir, limits, &f, data, error, error_size);
    }
    free(text);
    free(dir);
    return rc;
}

uint64_t aff_data_bytes(const struct aff_data *d)
{
    uint64_t n = (uint64_t)d->material_capacity * sizeof *d->materials +
                 (uint64_t)d->texture_capacity * sizeof *d->textures +
                 (uint64_t)d->matrix_capacity * sizeof *d->matrices +
                 (uint64_t)d->frame_capacity * sizeof *d->frames +
                 (uint64_t)d->animation_capacity * sizeof *d->animations +
                 (uint64_t)d->light_capacity * sizeof *d->lights;
    for (int f = 0; f < d->frame_count_nodes; f++) {
        const struct aff_group *g = &d->frames[f].group;
        n += (uint64_t)g->tri_capacity * sizeof *g->tris +
             (uint64_t)g->batch_capacity * sizeof *g->batches +
             (uint64_t)g->tpa_capacity * sizeof *g->tpas;
        for (uint32_t k = 0; k < g->tpa_count; k++)
            n += (uint64_t)g->tpas[k].key_count * sizeof *g->tpas[k].keys;
    }
    for (int a = 0; a < d->animation_count; a++) {
        const struct aff_animation *an = &d->animations[a];
        n += (uint64_t)(an->transl.key_count + an->rot.key_count + an->scale.key_count) *
             sizeof(struct aff_key) * 2;
        n += (uint64_t)an->visibility.key_count * (sizeof(double) + sizeof(int));
    }
    return n;
}

/* ------------------------------------------------------------ evaluation */

int aff_frame_matrix(const struct aff_data *d, int f, double t, double (*cache)[16], int *state,
                     double out[16])
{
    /* state: 0 unknown, 1 visible (cache valid), 2 hidden. */
    if (state[f] == 0) {
        const struct aff_frame *fr = &d->frames[f];
        double parent[16];
        int visible = 1;
        if (fr->parent < 0)
            aff_matrix_identity(parent);
        else
            visible = aff_frame_matrix(d, fr->parent, t, cache, state, parent);
        if (visible && fr->parent >= 0) {
            double node[16];
            const struct aff_animation *a = fr->animation >= 0 ? &d->animations[fr->animation]
                                                               : NULL;
            if (a && a->has_visibility && !aff_visibility_eval(&a->visibility, t))
                visible = 0;
            if (a)
                aff_node_matrix(a->has_transl ? &a->transl : NULL, a->has_rot ? &a->rot : NULL,
                                a->has_scale ? &a->scale : NULL, t, node);
            else
                aff_matrix_identity(node);
            aff_matrix_mul(cache[f], parent, d->matrices[fr->matrix]);
            aff_matrix_mul(cache[f], cache[f], node);
        } else if (visible) {
            aff_matrix_identity(cache[f]);
        }
        if (visible)
            for (int k = 0; k < 16; k++)
                if (!isfinite(cache[f][k]))
                    visible = 0;
        state[f] = visible ? 1 : 2;
    }
    if (state[f] != 1)
        return 0;
    memcpy(out, cache[f], sizeof cache[f]);
    return 1;
}
