/* SPDX-License-Identifier: Apache-2.0 */
/*
 * aff_anim.c - keyframe animation of the AFF (BART) format: Kochanek-Bartels
 * splines for translation and scale, a quaternion Kochanek-Bartels spline
 * evaluated with squad for rotation, node matrices, the camera, frame times
 * and linearly interpolated animated triangles.
 *
 * FORMAT.md is the format description shipped with the BART data
 * (../shared/bart/FORMAT.md); section numbers below are its sections.  The
 * maths follows it exactly, including the reference's quirks that change
 * results (sec. 7.4: conj used as the inverse, the sign rewrite of the key
 * array during setup, the 0.001 thresholds, the axis-angle round trip).
 * Where the order of floating-point operations is free, it is chosen to
 * match the reference code FORMAT.md describes, so results agree with it to
 * the last few bits, not only to the 6.1e-9 FORMAT.md quotes.
 *
 * Sources of the maths:
 *   - TCB splines: D. Kochanek and R. Bartels, "Interpolating splines with
 *     local tension, continuity, and bias control", SIGGRAPH 1984: the
 *     tension/continuity/bias tangents and their adjustment for unequal key
 *     spacing (FORMAT.md sec. 7.3).
 *   - Quaternion interpolation: K. Shoemake, "Animating rotation with
 *     quaternion curves", SIGGRAPH 1985 (slerp; squad is the spherical
 *     analogue of a Bezier/Hermite segment built from slerps); the log/exp
 *     form of the KB tangents on quaternions is FORMAT.md sec. 7.4.
 *
 * Robustness.  Every division has a non-zero denominator by construction or
 * by an explicit guard (see adj_factor, find_segment, quat_log, quat_exp,
 * quat_slerp, round_trip and aff_tpa_eval); no index depends on a key value
 * except through bounded loops.  Finite keys of ordinary size (not near the
 * double overflow threshold) give finite results; absurdly large values may
 * give NaN but never undefined behaviour.
 *
 * Segment layout (track->segments, key_count - 3 segments of SEG_STRIDE
 * doubles each; segment j spans keys j+1 .. j+2, FORMAT.md sec. 7.2):
 *
 *   index  0        1        2            3 ..
 *          t_{j+1}  t_{j+2}  t_{j+2}-t_{j+1}
 *   transl/scale: 3..5 C0, 6..8 C1, 9..11 C2, 12..14 C3 (P(u) = C0 + C1 u
 *                 + C2 u^2 + C3 u^3, FORMAT.md sec. 7.3)
 *   rot:          3..6 q1, 7..10 A, 11..14 B, 15..18 q2 (each w, x, y, z;
 *                 FORMAT.md sec. 7.4 step 4)
 */
#include "aff_anim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* pi to double precision (M_PI is POSIX, not C99). */
#define AFF_PI 3.14159265358979323846

/* Threshold of FORMAT.md sec. 7.4 on |sin| in log and exp and on sin(theta)
 * in slerp; the reference (Eberly's quaternion code) calls it the cutoff for
 * sin(angle) near zero. */
#define AFF_QUAT_SIN_EPSILON 0.001

#define SEG_TMIN 0
#define SEG_TMAX 1
#define SEG_TRANGE 2
#define SEG_DATA 3
#define SEG_STRIDE_SPLINE (SEG_DATA + 12)
#define SEG_STRIDE_ROT (SEG_DATA + 16)

static int segment_stride(int kind)
{
    return kind == AFF_TRACK_ROT ? SEG_STRIDE_ROT : SEG_STRIDE_SPLINE;
}

/* ------------------------------------------------------------ quaternions */

/* (w, x, y, z); not necessarily unit length (FORMAT.md sec. 7.4). */
struct quat {
    double w, x, y, z;
};

static struct quat quat_make(double w, double x, double y, double z)
{
    struct quat q;
    q.w = w;
    q.x = x;
    q.y = y;
    q.z = z;
    return q;
}

/* Hamilton product (w1w2 - v1.v2, w1v2 + w2v1 + v1 x v2), FORMAT.md 7.4. */
static struct quat quat_mul(struct quat a, struct quat b)
{
    return quat_make(a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
                     a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                     a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
                     a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x);
}

/* conj(q) = (w, -v).  FORMAT.md sec. 7.4: the reference uses it as the
 * inverse without dividing by |q|^2, which matters for non-unit keys. */
static struct quat quat_conj(struct quat q)
{
    return quat_make(q.w, -q.x, -q.y, -q.z);
}

static double quat_dot(struct quat a, struct quat b)
{
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

static struct quat quat_scale(struct quat q, double s)
{
    return quat_make(q.w * s, q.x * s, q.y * s, q.z * s);
}

static struct quat quat_add(struct quat a, struct quat b)
{
    return quat_make(a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z);
}

static struct quat quat_sub(struct quat a, struct quat b)
{
    return quat_make(a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z);
}

/* FORMAT.md sec. 7.4 log(q): if |w| < 1, theta = acos(w), s = sin(theta),
 * and if |s| >= 0.001 return (0, (theta/s) v); in every other case (0, v).
 * s > 0 whenever theta/s is taken, so no division by zero. */
static struct quat quat_log(struct quat q)
{
    if (fabs(q.w) < 1.0) {
        double theta = acos(q.w);
        double s = sin(theta);
        if (fabs(s) >= AFF_QUAT_SIN_EPSILON) {
            double c = theta / s;
            return quat_make(0.0, c * q.x, c * q.y, c * q.z);
        }
    }
    return quat_make(0.0, q.x, q.y, q.z);
}

/* FORMAT.md sec. 7.4 exp(q), vector part only: theta = |v|, s = sin(theta);
 * (cos theta, (s/theta) v) if |s| >= 0.001, else (cos theta, v).  |s| >=
 * 0.001 implies theta != 0. */
static struct quat quat_exp(struct quat q)
{
    double theta = sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    double s = sin(theta);
    double w = cos(theta);
    if (fabs(s) >= AFF_QUAT_SIN_EPSILON) {
        double c = s / theta;
        return quat_make(w, c * q.x, c * q.y, c * q.z);
    }
    return quat_make(w, q.x, q.y, q.z);
}

/* FORMAT.md sec. 7.4 slerp(p, q, h) (Shoemake 1985): c = p.q clamped to
 * [-1, 1], theta = acos(c); if sin(theta) < 0.001 return p, even for h = 1;
 * otherwise (sin((1-h) theta) p + sin(h theta) q) / sin(theta).  No
 * shortest-path sign test.  The reference multiplies by 1/sin(theta), and so
 * do we, for bit-level agreement. */
static struct quat quat_slerp(struct quat p, struct quat q, double h)
{
    double c = quat_dot(p, q);
    if (c < -1.0)
        c = -1.0;
    else if (c > 1.0)
        c = 1.0;
    double theta = acos(c);
    double s = sin(theta);
    if (!(s >= AFF_QUAT_SIN_EPSILON))
        return p;
    double inv = 1.0 / s;
    double c0 = sin((1.0 - h) * theta) * inv;
    double c1 = sin(h * theta) * inv;
    return quat_make(c0 * p.w + c1 * q.w, c0 * p.x + c1 * q.x, c0 * p.y + c1 * q.y,
                     c0 * p.z + c1 * q.z);
}

/* FORMAT.md sec. 7.4 "Key to quaternion": (cos(a/2), sin(a/2) axis) with the
 * angle a in radians and the axis as given (not normalised). */
static struct quat quat_from_angle_axis(double angle, double ax, double ay, double az)
{
    double half = 0.5 * angle;
    double s = sin(half);
    return quat_make(cos(half), s * ax, s * ay, s * az);
}

/* Degrees (file) to radians, as the reference's parser does: deg * pi / 180. */
static double radians(double degrees)
{
    return degrees * AFF_PI / 180.0;
}

/*
 * Angle (radians) and unit axis of q as the reference's quaternion-to-axis-
 * angle conversion computes them (FORMAT.md sec. 7.4): angle = 2 acos(w),
 * axis = v/|v|, or angle 0 and axis (1,0,0) when v is zero.  clamp_w: clamp
 * w to [-1, 1] first (FORMAT.md sec. 7.6.1); without it, |w| > 1 gives a NaN
 * angle, as in the reference.  |v|^2 > 0 makes 1/sqrt(|v|^2) finite.
 */
static void quat_to_angle_axis(struct quat q, int clamp_w, double *angle, double axis[3])
{
    double length2 = q.x * q.x + q.y * q.y + q.z * q.z;
    if (length2 > 0.0) {
        double w = q.w;
        if (clamp_w) {
            if (w > 1.0)
                w = 1.0;
            else if (w < -1.0)
                w = -1.0;
        }
        double inv = 1.0 / sqrt(length2);
        *angle = 2.0 * acos(w);
        axis[0] = q.x * inv;
        axis[1] = q.y * inv;
        axis[2] = q.z * inv;
    } else {
        *angle = 0.0;
        axis[0] = 1.0;
        axis[1] = 0.0;
        axis[2] = 0.0;
    }
}

/* Rotation matrix of a quaternion, row-major r[row*3+col]: the standard form
 * of FORMAT.md sec. 7.4, with the reference's grouping of the products. */
static void quat_to_matrix(struct quat q, double r[9])
{
    double x2 = q.x + q.x;
    double y2 = q.y + q.y;
    double z2 = q.z + q.z;
    double xx = q.x * x2;
    double xy = q.x * y2;
    double xz = q.x * z2;
    double yy = q.y * y2;
    double yz = q.y * z2;
    double zz = q.z * z2;
    double wx = q.w * x2;
    double wy = q.w * y2;
    double wz = q.w * z2;
    r[0] = 1.0 - (yy + zz);
    r[1] = xy - wz;
    r[2] = xz + wy;
    r[3] = xy + wz;
    r[4] = 1.0 - (xx + zz);
    r[5] = yz - wx;
    r[6] = xz - wy;
    r[7] = yz + wx;
    r[8] = 1.0 - (xx + yy);
}

static void store_quat(double *dst, struct quat q)
{
    dst[0] = q.w;
    dst[1] = q.x;
    dst[2] = q.y;
    dst[3] = q.z;
}

static struct quat load_quat(const double *src)
{
    return quat_make(src[0], src[1], src[2], src[3]);
}

/* --------------------------------------------------------- TCB weights */

/*
 * adj = 2 (t2 - t1) / den of FORMAT.md sec. 7.3 (Kochanek and Bartels
 * 1984, the adjustment for unequal key spacing), where den is t2 - t0
 * (adj0) or t3 - t1 (adj1).  den is zero only
 * when the same time is used three times around the key (t0 == t1 == t2) or
 * when times go back and forth (t0 == t2 != t1); the data has neither
 * (FORMAT.md sec. 7.6.3) and the reference would produce inf or NaN.  We
 * return 0 there: a zero tangent, which keeps the curve finite and inside
 * the neighbourhood of its keys; when the numerator is zero too (a
 * zero-length segment), 0 is also what every non-zero den gives.
 */
static double adj_factor(double t2_minus_t1, double den)
{
    if (den == 0.0)
        return 0.0;
    return 2.0 * t2_minus_t1 / den;
}

/* The four tangent weights of FORMAT.md sec. 7.3 for the segment from key
 * k[1] to key k[2] (k points at key j; k[0..3] are keys j..j+3). */
struct tcb_weights {
    double out0, out1, in0, in1;
};

static struct tcb_weights tcb_weights(const struct aff_key *k)
{
    struct tcb_weights w;
    double adj0 = adj_factor(k[2].time - k[1].time, k[2].time - k[0].time);
    double adj1 = adj_factor(k[2].time - k[1].time, k[3].time - k[1].time);
    double t1 = k[1].tension;
    double c1 = k[1].continuity;
    double b1 = k[1].bias;
    double t2 = k[2].tension;
    double c2 = k[2].continuity;
    double b2 = k[2].bias;
    w.out0 = 0.5 * adj0 * (1.0 - t1) * (1.0 + c1) * (1.0 + b1);
    w.out1 = 0.5 * adj0 * (1.0 - t1) * (1.0 - c1) * (1.0 - b1);
    w.in0 = 0.5 * adj1 * (1.0 - t2) * (1.0 - c2) * (1.0 + b2);
    w.in1 = 0.5 * adj1 * (1.0 - t2) * (1.0 + c2) * (1.0 - b2);
    return w;
}

static void store_interval(double *seg, const struct aff_key *k)
{
    seg[SEG_TMIN] = k[1].time;
    seg[SEG_TMAX] = k[2].time;
    seg[SEG_TRANGE] = k[2].time - k[1].time;
}

/* ------------------------------------------------------------ setup */

/* FORMAT.md sec. 7.3: Hermite coefficients of each segment of a transl or
 * scale track. */
static void setup_spline(struct aff_track *track)
{
    int segments = track->key_count - 3;
    for (int j = 0; j < segments; j++) {
        const struct aff_key *k = &track->keys[j];
        double *seg = &track->segments[(size_t)j * SEG_STRIDE_SPLINE];
        struct tcb_weights w = tcb_weights(k);
        store_interval(seg, k);
        for (int c = 0; c < 3; c++) {
            double d = k[2].v[c] - k[1].v[c];
            double t_out = w.out1 * d + w.out0 * (k[1].v[c] - k[0].v[c]);
            double t_in = w.in1 * (k[3].v[c] - k[2].v[c]) + w.in0 * d;
            seg[SEG_DATA + c] = k[1].v[c];
            seg[SEG_DATA + 3 + c] = t_out;
            seg[SEG_DATA + 6 + c] = 3.0 * d - 2.0 * t_out - t_in;
            seg[SEG_DATA + 9 + c] = -2.0 * d + t_out + t_in;
        }
    }
}

/*
 * FORMAT.md sec. 7.4 setup, segment by segment in increasing order, on a
 * working copy of the key angles in radians (angle[i] for key i).
 *
 * Step 2 rewrites key j+2 (its angle[] entry and track->keys[j+2], the
 * latter in degrees) whenever q1.q2 < 0.  Later segments rebuild their
 * quaternions from the rewritten key, which then has a unit axis, while in
 * the current segment q3 (key j+3) is still the value as read, because it is
 * only rewritten, if at all, by the next segment.  Rebuilding q0..q3 from the
 * key array in every iteration gives exactly that.
 */
static void setup_rotation(struct aff_track *track, double *angle)
{
    struct aff_key *keys = track->keys;
    int segments = track->key_count - 3;
    for (int j = 0; j < segments; j++) {
        struct quat q[4];
        /* Step 1: q0..q3 from keys j..j+3 as they are now. */
        for (int i = 0; i < 4; i++) {
            const struct aff_key *k = &keys[j + i];
            q[i] = quat_from_angle_axis(angle[j + i], k->v[0], k->v[1], k->v[2]);
        }
        /* Step 2: keep consecutive quaternions at an acute angle, and write
         * the negated q2 back into key j+2. */
        if (quat_dot(q[1], q[2]) < 0.0) {
            double axis[3];
            q[2] = quat_scale(q[2], -1.0);
            quat_to_angle_axis(q[2], 0, &angle[j + 2], axis);
            keys[j + 2].v[0] = axis[0];
            keys[j + 2].v[1] = axis[1];
            keys[j + 2].v[2] = axis[2];
            keys[j + 2].v[3] = angle[j + 2] * 180.0 / AFF_PI;
        }
        /* Step 3: the TCB tangents of Kochanek and Bartels 1984, taken in
         * the log domain: applied to log(conj(q_i) q_{i+1}). */
        struct tcb_weights w = tcb_weights(&keys[j]);
        struct quat d = quat_log(quat_mul(quat_conj(q[1]), q[2]));
        struct quat l0 = quat_log(quat_mul(quat_conj(q[0]), q[1]));
        struct quat l2 = quat_log(quat_mul(quat_conj(q[2]), q[3]));
        struct quat t_out = quat_add(quat_scale(d, w.out1), quat_scale(l0, w.out0));
        struct quat t_in = quat_add(quat_scale(d, w.in0), quat_scale(l2, w.in1));
        /* Step 4: inner control points of squad (Shoemake 1985). */
        struct quat a = quat_mul(q[1], quat_exp(quat_scale(quat_sub(t_out, d), 0.5)));
        struct quat b = quat_mul(q[2], quat_exp(quat_scale(quat_sub(d, t_in), 0.5)));

        double *seg = &track->segments[(size_t)j * SEG_STRIDE_ROT];
        store_interval(seg, &keys[j]);
        store_quat(&seg[SEG_DATA], q[1]);
        store_quat(&seg[SEG_DATA + 4], a);
        store_quat(&seg[SEG_DATA + 8], b);
        store_quat(&seg[SEG_DATA + 12], q[2]);
    }
}

int aff_track_init(struct aff_track *track, int kind, struct aff_key *keys, int key_count)
{
    if (!track) {
        free(keys);
        return -1;
    }
    memset(track, 0, sizeof(*track));
    if (!keys || key_count < 4 ||
        (kind != AFF_TRACK_TRANSL && kind != AFF_TRACK_ROT && kind != AFF_TRACK_SCALE)) {
        free(keys);
        return -1;
    }
    size_t segments = (size_t)key_count - 3;
    size_t stride = (size_t)segment_stride(kind);
    if (segments > (size_t)-1 / (stride * sizeof(double))) {
        free(keys);
        return -1;
    }
    double *seg = malloc(segments * stride * sizeof(double));
    double *angle = NULL;
    if (seg && kind == AFF_TRACK_ROT) {
        if ((size_t)key_count > (size_t)-1 / sizeof(double))
            angle = NULL;
        else
            angle = malloc((size_t)key_count * sizeof(double));
        if (!angle) {
            free(seg);
            seg = NULL;
        }
    }
    if (!seg) {
        free(keys);
        return -1;
    }
    track->kind = kind;
    track->key_count = key_count;
    track->keys = keys;
    track->segments = seg;
    if (kind == AFF_TRACK_ROT) {
        for (int i = 0; i < key_count; i++)
            angle[i] = radians(keys[i].v[3]);
        setup_rotation(track, angle);
        free(angle);
    } else {
        setup_spline(track);
    }
    return 0;
}

void aff_track_release(struct aff_track *track)
{
    if (!track)
        return;
    free(track->keys);
    free(track->segments);
    memset(track, 0, sizeof(*track));
}

/* ------------------------------------------------------------ evaluation */

/*
 * FORMAT.md sec. 7.2 lookup: t <= t_1 (or NaN): segment 0, u = 0; else
 * t >= t_{n-2}: last segment, u = 1; else the first segment j in file order
 * with t < t_{j+2}, u = (t - t_{j+1}) / (t_{j+2} - t_{j+1}).
 *
 * The selected segment has t_{j+1} <= t < t_{j+2} (segment 0 by the first
 * test, later ones because the previous segment, ending at t_{j+1}, was
 * skipped), so its range is positive: zero-length segments are never
 * selected.  The guard on the range only catches NaN key times.
 */
static const double *find_segment(const struct aff_track *track, double t, double *u)
{
    int count = track->key_count - 3;
    size_t stride = (size_t)segment_stride(track->kind);
    const double *first = track->segments;
    const double *last = &track->segments[(size_t)(count - 1) * stride];
    if (!(first[SEG_TMIN] < t)) {
        *u = 0.0;
        return first;
    }
    if (!(t < last[SEG_TMAX])) {
        *u = 1.0;
        return last;
    }
    for (int j = 0; j < count; j++) {
        const double *seg = &track->segments[(size_t)j * stride];
        if (t < seg[SEG_TMAX]) {
            double range = seg[SEG_TRANGE];
            *u = range > 0.0 ? (t - seg[SEG_TMIN]) / range : 0.0;
            return seg;
        }
    }
    /* Not reached: the last segment satisfies t < t_{n-2}. */
    *u = 1.0;
    return last;
}

static int track_is_set_up(const struct aff_track *track)
{
    return track && track->segments && track->keys && track->key_count >= 4;
}

static void identity3(double r[9])
{
    for (int i = 0; i < 9; i++)
        r[i] = (i % 4 == 0) ? 1.0 : 0.0;
}

/* Squad of FORMAT.md sec. 7.4 (Shoemake 1985):
 * Q = slerp(slerp(q1, q2, s), slerp(A, B, s), 2 s (1 - s)). */
static struct quat eval_squad(const struct aff_track *track, double t)
{
    double s;
    const double *seg = find_segment(track, t, &s);
    struct quat p = load_quat(&seg[SEG_DATA]);
    struct quat a = load_quat(&seg[SEG_DATA + 4]);
    struct quat b = load_quat(&seg[SEG_DATA + 8]);
    struct quat q = load_quat(&seg[SEG_DATA + 12]);
    struct quat pq = quat_slerp(p, q, s);
    struct quat ab = quat_slerp(a, b, s);
    return quat_slerp(pq, ab, 2.0 * s * (1.0 - s));
}

void aff_track_eval_quat(const struct aff_track *track, double t, double q[4])
{
    if (!track_is_set_up(track) || track->kind != AFF_TRACK_ROT) {
        q[0] = 1.0;
        q[1] = q[2] = q[3] = 0.0;
        return;
    }
    store_quat(q, eval_squad(track, t));
}

void aff_track_eval(const struct aff_track *track, double t, double *out)
{
    if (!track_is_set_up(track)) {
        int kind = track ? track->kind : AFF_TRACK_TRANSL;
        if (kind == AFF_TRACK_ROT)
            identity3(out);
        else
            out[0] = out[1] = out[2] = (kind == AFF_TRACK_SCALE) ? 1.0 : 0.0;
        return;
    }
    if (track->kind == AFF_TRACK_ROT) {
        /* FORMAT.md sec. 7.4: Q to axis-angle and back, i.e. the unit
         * quaternion (Q.w, sqrt(1 - Q.w^2) v/|v|), with w clamped to
         * [-1, 1] (sec. 7.6.1; the reference gives NaN for |Q.w| > 1). */
        double angle;
        double axis[3];
        quat_to_angle_axis(eval_squad(track, t), 1, &angle, axis);
        quat_to_matrix(quat_from_angle_axis(angle, axis[0], axis[1], axis[2]), out);
        return;
    }
    double u;
    const double *seg = find_segment(track, t, &u);
    /* FORMAT.md sec. 7.3 P(u), in Horner form as the reference evaluates it. */
    for (int c = 0; c < 3; c++)
        out[c] = seg[SEG_DATA + c] +
                 u * (seg[SEG_DATA + 3 + c] +
                      u * (seg[SEG_DATA + 6 + c] + u * seg[SEG_DATA + 9 + c]));
}

int aff_visibility_eval(const struct aff_visibility *vis, double t)
{
    if (!vis || vis->key_count <= 0 || !vis->times || !vis->flags)
        return 1;
    /* The reference's scan: return the current flag at the first key that
     * lies after t (while t is at or after the previous key), or the last
     * key's flag when t is at or after it.  Visible before the first key. */
    int visible = 1;
    double previous = -HUGE_VAL;
    for (int q = 0; q < vis->key_count; q++) {
        if (t >= previous && t < vis->times[q])
            return visible;
        if (t >= vis->times[q] && q == vis->key_count - 1)
            return vis->flags[q] != 0;
        visible = vis->flags[q] != 0;
        previous = vis->times[q];
    }
    return 1;
}

/* The roles of aff_node_matrix and aff_camera_eval: a track of the wrong
 * kind for its argument (a rot track passed as transl, say) is treated as
 * absent, so a mix-up can never write 9 values into a 3-vector. */
static void eval_vec3(const struct aff_track *track, double t, double fallback, double out[3])
{
    if (track && track->kind != AFF_TRACK_ROT) {
        aff_track_eval(track, t, out);
        return;
    }
    out[0] = out[1] = out[2] = fallback;
}

static void eval_rotation(const struct aff_track *track, double t, double r[9])
{
    if (track && track->kind == AFF_TRACK_ROT)
        aff_track_eval(track, t, r);
    else
        identity3(r);
}

void aff_node_matrix(const struct aff_track *transl, const struct aff_track *rot,
                     const struct aff_track *scale, double t, double m[16])
{
    double r[9];
    double s[3];
    double p[3];
    eval_rotation(rot, t, r);
    eval_vec3(scale, t, 1.0, s);
    eval_vec3(transl, t, 0.0, p);
    /* M = T R S (FORMAT.md sec. 7.1): M[i][j] = R[i][j] S[j], translation in
     * column 3; stored column-major. */
    for (int row = 0; row < 3; row++) {
        for (int col = 0; col < 3; col++)
            m[col * 4 + row] = r[row * 3 + col] * s[col];
        m[12 + row] = p[row];
        m[row * 4 + 3] = 0.0;
    }
    m[15] = 1.0;
}

void aff_camera_eval(const struct aff_track *transl, const struct aff_track *rot, double t,
                     double eye[3], double dir[3], double up[3])
{
    double r[9];
    eval_vec3(transl, t, 0.0, eye);
    eval_rotation(rot, t, r);
    /* FORMAT.md sec. 8: direction R (0,0,-1), the negated third column;
     * up R (0,1,0), the second column. */
    for (int i = 0; i < 3; i++) {
        dir[i] = -r[i * 3 + 2];
        up[i] = r[i * 3 + 1];
    }
}

double aff_frame_time(double t0, double t1, int frames, int f)
{
    if (frames <= 1)
        return t0;
    if (f == frames - 1)
        return t1;
    return t0 + (t1 - t0) * (double)f / (double)(frames - 1);
}

/* a + r (b - a) for r in [0, 1], kept between a and b so that rounding can
 * never leave the float range. */
static float lerp_float(float a, float b, double r)
{
    double da = (double)a;
    double db = (double)b;
    double v = da + r * (db - da);
    double lo = da < db ? da : db;
    double hi = da < db ? db : da;
    if (v < lo)
        v = lo;
    else if (v > hi)
        v = hi;
    return (float)v;
}

static void tpa_copy(const struct aff_tpa_key *k, float p[9], float n[9])
{
    memcpy(p, k->p, sizeof(k->p));
    memcpy(n, k->n, sizeof(k->n));
}

void aff_tpa_eval(const struct aff_tpa_key *keys, int key_count, double t, float p[9], float n[9])
{
    if (!keys || key_count < 1) {
        memset(p, 0, 9 * sizeof(float));
        memset(n, 0, 9 * sizeof(float));
        return;
    }
    /* FORMAT.md sec. 7.5. */
    if (t < keys[0].time) {
        tpa_copy(&keys[0], p, n);
        return;
    }
    if (t > keys[key_count - 1].time) {
        tpa_copy(&keys[key_count - 1], p, n);
        return;
    }
    for (int k = 0; k + 1 < key_count; k++) {
        const struct aff_tpa_key *a = &keys[k];
        const struct aff_tpa_key *b = &keys[k + 1];
        if (a->time <= t && t <= b->time) {
            double den = b->time - a->time;
            double r = den > 0.0 ? (t - a->time) / den : 0.0;
            if (!(r >= 0.0))
                r = 0.0;
            else if (r > 1.0)
                r = 1.0;
            for (int i = 0; i < 9; i++) {
                p[i] = lerp_float(a->p[i], b->p[i], r);
                n[i] = lerp_float(a->n[i], b->n[i], r);
            }
            return;
        }
    }
    /* One key with t == t_0, a NaN t, or NaN key times: key 0. */
    tpa_copy(&keys[0], p, n);
}

void aff_matrix_identity(double m[16])
{
    for (int i = 0; i < 16; i++)
        m[i] = i % 5 == 0 ? 1.0 : 0.0;
}

void aff_matrix_mul(double out[16], const double a[16], const double b[16])
{
    double product[16];
    /* Element i is (row i % 4, column i / 4), a dot product of a row of a
     * with a column of b, summed from 0.0 in this order as base/mat4.h
     * sums it, so the loader's matrices are bit-identical to the core's
     * (signed zeros included). */
    for (int i = 0; i < 16; i++) {
        const int row = i % 4, col = i / 4;
        product[i] = 0.0 + a[row] * b[4 * col] + a[4 + row] * b[4 * col + 1] +
                     a[8 + row] * b[4 * col + 2] + a[12 + row] * b[4 * col + 3];
    }
    memcpy(out, product, sizeof(product));
}
