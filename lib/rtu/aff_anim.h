/* SPDX-License-Identifier: Apache-2.0 */
/*
 * aff_anim.h - keyframe animation maths of the AFF (BART) scene format.
 *
 * FORMAT.md below is the format description shipped with the BART data
 * (../shared/bart/FORMAT.md next to the checkout).  This module implements
 * its sections 5 (frame times), 7 (keyframe tracks, node matrices, animated
 * triangles) and 8 (camera), and nothing else: no parsing, no rt.h.  It
 * depends only on the C library (<math.h>, <stdlib.h>, <string.h>), so a
 * test can compile it on its own.
 *
 * Conventions.
 *   - Times are seconds of animation time, as in the files.
 *   - Angles in keys are degrees, as in the files (FORMAT.md sec. 4); the
 *     maths converts them with deg * pi / 180 exactly as the reference does.
 *   - Values read from a file are float32 widened to double (FORMAT.md
 *     sec. 1); all maths is double.
 *   - Rotation matrices are returned row-major, R[row][col] at out[row*3+col].
 *     Node matrices are returned column-major like OpenGL and rt.h: element
 *     (row r, column c) at m[c*4+r]; points are column vectors, p' = M p.
 *
 * Nothing here keeps global state; every function is thread-safe for
 * distinct outputs, and evaluation never modifies a track.
 */
#ifndef RT_RTU_AFF_ANIM_H
#define RT_RTU_AFF_ANIM_H

/* One key of a transl/rot/scale track, as read from the file (floats were
 * parsed as float32 and widened; see FORMAT.md sec. 1). For transl and scale,
 * v[0..2] is the value; for rot, v[0..2] is the axis (NOT normalised) and v[3]
 * the angle in degrees. */
struct aff_key {
    double time;
    double v[4];
    double tension, continuity, bias;
};

/* A spline track after setup (FORMAT.md 7.2-7.4). */
struct aff_track {
    int kind;             /* AFF_TRACK_TRANSL, AFF_TRACK_ROT, AFF_TRACK_SCALE */
    int key_count;        /* >= 4 */
    struct aff_key *keys; /* owned; rot keys are rewritten by setup (7.4 step 2) */
    double *segments;     /* owned; per-segment precomputed data, layout in aff_anim.c */
};
enum { AFF_TRACK_TRANSL, AFF_TRACK_ROT, AFF_TRACK_SCALE };

/*
 * Sets up *track from key_count keys in file order and takes ownership of
 * keys (allocated with malloc; aff_track_release frees it).  Precomputes the
 * key_count - 3 segments of FORMAT.md sec. 7.2: Hermite coefficients for
 * transl and scale (7.3), squad control points for rot (7.4).
 *
 * For rot, setup rewrites keys in place as the reference does (FORMAT.md
 * sec. 7.4 step 2): a key whose quaternion was negated gets the angle (in
 * degrees) and unit axis of the negated quaternion.  Other keys, and all
 * transl/scale keys, are left exactly as given.
 *
 * Returns 0 on success.  Returns -1 when key_count < 4, kind is not one of
 * the three kinds, keys is NULL or an allocation fails; then keys (if not
 * NULL) is freed and *track is zeroed.  Any finite key values are accepted,
 * including non-increasing and repeated times (never a division by zero).
 */
int aff_track_init(struct aff_track *track, int kind, struct aff_key *keys, int key_count);

/* Frees what the track owns and zeroes it.  Accepts NULL and a zeroed track. */
void aff_track_release(struct aff_track *track);

/*
 * Evaluates the track at time t (FORMAT.md sec. 7.2 lookup and clamping).
 * transl/scale: writes 3 values (7.3); rot: writes the 3x3 rotation matrix
 * R[row][col] row-major in out[0..8] (7.4, including the axis-angle round
 * trip), with the recommended clamp of w to [-1,1] of 7.6.1, so no NaN is
 * ever produced for finite keys of ordinary size.  A NaN t evaluates as
 * t <= t_1 (segment 0, u = 0), as the reference's comparisons do.  out
 * must hold 9 doubles for a rot track and 3 otherwise.  A zeroed track
 * (failed init) writes the identity of its kind: (0,0,0) for transl.
 */
void aff_track_eval(const struct aff_track *track, double t, double *out);

/*
 * Rot tracks only: the squad quaternion Q = (w, x, y, z) of FORMAT.md sec.
 * 7.4 at time t, before the axis-angle round trip and before any clamp.
 * With the non-unit axes of the data, Q.w can exceed 1 (sec. 7.6.1); this
 * lets a test see where the clamp of aff_track_eval takes effect.  Writes
 * the identity quaternion for a track that is not a set-up rot track.
 */
void aff_track_eval_quat(const struct aff_track *track, double t, double q[4]);

/* Visibility track (7.1). */
struct aff_visibility {
    int key_count;
    double *times;
    int *flags;
};

/*
 * Returns 1 when visible at time t, 0 when hidden (FORMAT.md sec. 7.1):
 * visible before the first key; from then on the flag (non-zero = visible)
 * of the latest key whose time is <= t.  Keys are scanned in file order as
 * the reference does; for non-decreasing times that is exactly the rule
 * above (with equal times, the later key wins).  NULL, or no keys: visible.
 */
int aff_visibility_eval(const struct aff_visibility *vis, double t);

/*
 * The node matrix M(t) = T(t) R(t) S(t) of FORMAT.md sec. 7.1 as a
 * column-major 4x4 double matrix (element (row r, col c) at m[c*4+r]).  Any
 * track may be NULL: it contributes the identity (T = 0, R = I, S = 1).
 * Scale multiplies the columns of R: M[i][j] = R[i][j] S[j].  A track of
 * the wrong kind for its argument (rot passed as transl or scale, or
 * transl/scale passed as rot) is treated as NULL.
 */
void aff_node_matrix(const struct aff_track *transl, const struct aff_track *rot,
                     const struct aff_track *scale, double t, double m[16]);

/* The identity, and out = a * b (out may alias a or b), for the same
 * column-major matrices.  rtu sees include/rt only, so the loader keeps
 * its own two matrix helpers rather than the core's base/mat4.h. */
void aff_matrix_identity(double m[16]);
void aff_matrix_mul(double out[16], const double a[16], const double b[16]);

/*
 * Camera (FORMAT.md sec. 8) at time t: eye = T(t), view direction =
 * R(t) (0,0,-1), up = R(t) (0,1,0).  A NULL transl gives eye (0,0,0) and a
 * NULL rot gives direction (0,0,-1) and up (0,1,0); a caller with a `v`
 * statement should use its from/at/up instead (sec. 8, last paragraph).
 * Tracks of the wrong kind are treated as NULL, as in aff_node_matrix.
 */
void aff_camera_eval(const struct aff_track *transl, const struct aff_track *rot, double t,
                     double eye[3], double dir[3], double up[3]);

/*
 * Frame time of FORMAT.md sec. 5: t_f = t0 + (t1 - t0) f / (N - 1), with
 * N = frames.  frames <= 1 gives t0; f == frames - 1 gives exactly t1.  f
 * outside [0, frames - 1] extrapolates along the same line.
 */
double aff_frame_time(double t0, double t1, int frames, int f);

/*
 * Animated triangle, FORMAT.md sec. 7.5: keys of (time, 3 vertices xyz,
 * 3 normals xyz).  Writes the interpolated 9 position and 9 normal values
 * (normals NOT normalised; the caller normalises).  t before the first key
 * gives key 0, after the last key the last key; otherwise the first k in
 * file order with t_k <= t <= t_{k+1} is interpolated linearly.  When
 * t_k == t_{k+1} (only possible at t == t_k) key k is used.  A NaN t gives
 * key 0.  key_count < 1 or keys NULL: writes zeros.
 */
struct aff_tpa_key {
    double time;
    float p[9];
    float n[9];
};
void aff_tpa_eval(const struct aff_tpa_key *keys, int key_count, double t, float p[9], float n[9]);

#endif
