/* SPDX-License-Identifier: Apache-2.0 */
/*
 * aff_internal.h - the AFF (BART) scene loader's in-memory scene.
 *
 * The loader is split in three (FORMAT.md is ../shared/bart/FORMAT.md, the
 * description of the format we implement):
 *   aff_parse.c  text -> struct aff_data: statement-level, character-level
 *                dispatch (FORMAT.md sec. 2), includes, transform blocks,
 *                materials, geometry, keyframes.  Knows nothing of rt.h.
 *   aff_anim.c   the keyframe maths (FORMAT.md sec. 7 and 8).
 *   aff_scene.c  struct aff_data -> Tracelist objects and per-frame
 *                instances, the public rtu*AFF* entry points.
 *
 * Grouping (Wald, Benthin and Slusallek (2003) sec. 4.1, "for scene-graph-like applications this
 * grouping is often trivial"): geometry is grouped by the innermost
 * animated transform ('x' block) enclosing it.  Each such *frame* owns one
 * object, built once and instanced every frame under the product of the
 * transforms above it; geometry under no 'x' goes to the root frame, the
 * one static object.  Static 'xs' transforms are not baked by the parser:
 * every batch of triangles keeps the static matrix relative to its frame,
 * and aff_scene.c hands it to the API's matrix stack while recording, as a
 * scene-graph application would.  Animated triangles ('tpa') of a frame
 * form that frame's one unstructured object, updated every frame.
 */
#ifndef RT_RTU_AFF_INTERNAL_H
#define RT_RTU_AFF_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "rtu/aff_anim.h"

#if defined(__GNUC__)
#define AFF_HIDDEN __attribute__((visibility("hidden")))
#else
#define AFF_HIDDEN
#endif

/* Longest error message, terminator included. */
#define AFF_ERROR_SIZE 512
/* Include nesting limit: a file that includes itself fails cleanly. */
#define AFF_MAX_INCLUDE_DEPTH 32
/* Transform block nesting limit (the data nests 15 deep). */
#define AFF_MAX_BLOCK_DEPTH 256

/*
 * Resource limits of one load (docs/aff.md, "Files and resource limits").
 * The per-file counts (checked against the bytes left) and the nesting
 * limits do not bound the whole: nine 10-line files that each include the
 * next ten times ask for 10^8 triangles.  So the work is counted per
 * expansion -- every inclusion of a file counts its bytes and triangles
 * again -- against budgets derived from the input, the distinct files
 * read (each counted once, by device and inode):
 *   bytes read     <= AFF_READ_PER_INPUT x input + AFF_READ_BASE,
 *                     at most AFF_READ_CAP;
 *   triangles made <= input / AFF_INPUT_PER_TRIANGLE + AFF_TRIANGLES_BASE,
 *                     at most AFF_TRIANGLES_CAP,
 * unless the caller gives a budget (rtuLoadAFFv), which replaces the
 * derived one.  A parsed triangle takes 96 bytes (struct aff_triangle), so
 * the parsed geometry of n input bytes stays below 24 n + 6 MiB (twice
 * that while an array doubles), the spheres of a file of spheres included.
 */
#define AFF_DEFAULT_MAX_FILE_BYTES ((uint64_t)256 << 20)
#define AFF_READ_PER_INPUT 8
#define AFF_READ_BASE ((uint64_t)1 << 20)
#define AFF_READ_CAP ((uint64_t)1 << 30)
#define AFF_INPUT_PER_TRIANGLE 4
#define AFF_TRIANGLES_BASE 65536
#define AFF_TRIANGLES_CAP ((uint64_t)1 << 24)

struct aff_limits {
    uint64_t max_file_bytes; /* size of one file */
    uint64_t max_read_bytes; /* bytes read in all; 0: derived (above) */
    uint64_t max_triangles;  /* triangles made in all; 0: derived (above) */
    int any_directory;       /* includes and textures may lie anywhere */
    /* Includes from memory instead of the filesystem (the fuzz target's
     * several files in one input): the text of include `name` and an id
     * that is the same for the same file, or -1 when there is none.  The
     * text stays the caller's.  NULL: the filesystem. */
    int (*include_text)(void *user, const char *name, const char **text, size_t *length,
                        uint64_t *id);
    void *include_user;
};

/* The defaults: 256 MiB per file, derived budgets, the top file's tree. */
AFF_HIDDEN void aff_limits_default(struct aff_limits *limits);

/* aff_file.c: a file the scene names, open and checked, not yet read. */
struct aff_file {
    int fd;
    uint64_t size, device, inode;
};

/* realpath of `directory` ("" or NULL: the current directory), malloc'd;
 * NULL on failure (errno set). */
AFF_HIDDEN char *aff_file_root(const char *directory);

/* Opens `path` for reading without blocking.  With `root` (a realpath'd
 * directory) non-NULL the path, links and ".." resolved, must lie inside
 * it.  It must be a regular file of at most max_bytes bytes.  Returns 0,
 * or -1 with the reason in `why` (no "file:line: " prefix). */
AFF_HIDDEN int aff_file_open(const char *path, const char *root, uint64_t max_bytes,
                             struct aff_file *file, char *why, size_t why_size);
/* Reads the open file whole (malloc'd, not terminated); NULL with *oom set
 * when memory ran out, clear on a read error. */
AFF_HIDDEN char *aff_file_read(struct aff_file *file, size_t *length, int *oom);
AFF_HIDDEN void aff_file_close(struct aff_file *file);
/* aff_file_open and aff_file_close: may this file be read? (textures,
 * which rtuLoadImage then reads.) */
AFF_HIDDEN int aff_file_check(const char *path, const char *root, uint64_t max_bytes, char *why,
                              size_t why_size);

/* 'fm' (FORMAT.md sec. 3.2); 'f' is mapped onto it. */
struct aff_material {
    float ambient[3], diffuse[3], specular[3];
    float shine, transmittance, ior;
};

/* One triangle in its batch's local space.  Normals are all zero when the
 * primitive has none (the renderer then shades with the geometric normal). */
struct aff_triangle {
    float p[9];
    float n[9];
    float uv[6];
};

/* The triangles of one statement (mesh, polygon, cone, ...): one static
 * matrix (index into aff_data.matrices), one material, one texture. */
struct aff_batch {
    uint32_t first, count; /* range in the group's triangles */
    int matrix;
    int material; /* -1: none was set (a default is used) */
    int texture;  /* index into aff_data.textures, -1: untextured */
    int has_uv;
};

/* Animated triangle (FORMAT.md sec. 3.3 and 7.5); keys are stored already
 * transformed by the static matrix current at the statement. */
struct aff_tpa {
    int key_count;
    struct aff_tpa_key *keys;
    int material;
};

/* Geometry of one frame: the triangles of its static object and the
 * animated triangles of its unstructured object. */
struct aff_group {
    struct aff_triangle *tris;
    uint32_t tri_count, tri_capacity;
    struct aff_batch *batches;
    uint32_t batch_count, batch_capacity;
    struct aff_tpa *tpas;
    uint32_t tpa_count, tpa_capacity;
};

/* A frame: the root (index 0) or one instantiated 'x' block. */
struct aff_frame {
    int parent;   /* -1 for the root */
    int matrix;   /* static matrix from the parent frame to the block */
    char *name;   /* 'x' name; NULL for the root */
    int animation; /* index into animations, -1: identity (sec. 3.4) */
    struct aff_group group;
};

/* A 'k' block (FORMAT.md sec. 7.1). */
struct aff_animation {
    char *name;
    int has_transl, has_rot, has_scale, has_visibility;
    struct aff_track transl, rot, scale;
    struct aff_visibility visibility;
};

struct aff_light {
    float position[3];
    float color[3];
    char *name;    /* 'la' name, NULL for 'l' */
    int animation; /* resolved 'k' of an 'la', -1 otherwise */
};

struct aff_texture {
    char *name;
    char *path; /* resolved against the top file's directory */
    char where[80]; /* "file:line" of its first use, for load errors */
};

struct aff_data {
    char *directory; /* of the top file, "" for the current directory */
    char *root;      /* its realpath: textures must lie below; NULL: anywhere */
    uint64_t max_file_bytes; /* of the load's limits, for the textures */

    /* 'v' (sec. 3.1) */
    int has_view;
    float from[3], at[3], up[3];
    float fov_degrees, hither;
    int resolution[2];
    /* 'b', 'am', 'a' */
    int has_background, has_ambient, has_animation_range;
    float background[3], ambient[3];
    float t0, t1;
    int frame_count;

    struct aff_material *materials;
    int material_count, material_capacity;
    struct aff_texture *textures;
    int texture_count, texture_capacity;
    double (*matrices)[16]; /* column-major (OpenGL layout) */
    int matrix_count, matrix_capacity;
    struct aff_frame *frames; /* frames[0] is the root */
    int frame_count_nodes, frame_capacity;
    struct aff_animation *animations;
    int animation_count, animation_capacity;
    struct aff_light *lights;
    int light_count, light_capacity;
    int camera; /* animation named "camera", -1 when absent */

    /* Counts for statistics: triangles as instantiated. */
    uint64_t static_triangles, animated_triangles, tpa_triangles;
};

/* Reads the file at path and everything it includes, within `limits`
 * (NULL: the defaults).  On failure returns -1 with "file:line: reason" in
 * error (line 0: the file as a whole) and *data released; never crashes on
 * malformed input. */
AFF_HIDDEN int aff_parse_file(const char *path, const struct aff_limits *limits,
                              struct aff_data *data, char *error, size_t error_size);

/* The same on a text in memory named `name`; includes are resolved with
 * the filesystem against `directory` (NULL: includes are an error, which
 * is what the fuzz target uses; textures then resolve against the current
 * directory and must lie inside it). */
AFF_HIDDEN int aff_parse_text(const char *name, const char *text, size_t length,
                              const char *directory, const struct aff_limits *limits,
                              struct aff_data *data, char *error, size_t error_size);

/* Bytes the parsed scene holds (its arrays at their capacity), for the
 * fuzz target's memory-bound property. */
AFF_HIDDEN uint64_t aff_data_bytes(const struct aff_data *data);

AFF_HIDDEN void aff_data_release(struct aff_data *data);

/* World matrix of frame f at time t (column-major); returns 0 when the
 * frame or one of its ancestors is hidden at t (visibility track) or its
 * matrix is not finite.  `cache` holds frame_count_nodes matrices and
 * `state` as many ints, zeroed by the caller before the first call for a
 * given t. */
AFF_HIDDEN int aff_frame_matrix(const struct aff_data *data, int f, double t, double (*cache)[16],
                                int *state, double out[16]);

/* The parsed scene behind a loaded RTUaffscene (aff_scene.c), read-only,
 * owned by the scene; NULL for NULL.  For tools compiled together with
 * the loader (bench/bench_bart.c evaluates the 'tpa' triangles of a frame
 * with it); not part of rtu.h. */
struct rtu_aff_scene;
AFF_HIDDEN const struct aff_data *aff_scene_data(const struct rtu_aff_scene *scene);

/* The second half of rtuLoadAFF (which is aff_parse_file followed by this):
 * records an already parsed scene in the current context.  Takes ownership
 * of *data in every case, moving it into the scene or releasing it on
 * failure, and leaves it zeroed; `name` stands for the file in messages.
 * Returns NULL on failure with the reason in rtuAFFError(), leaving no
 * object or texture behind.  For the fuzz target (conformance/fuzz), which
 * parses text from memory. */
struct rtu_aff_scene;
AFF_HIDDEN struct rtu_aff_scene *aff_scene_create(struct aff_data *data, const char *name);

#endif
