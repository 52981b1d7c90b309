/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_standalone.c - a scene held and updated with no API context, as
 * an MPI worker will: recording (scene/recording.c), definition, instances,
 * preparation with its change set (scene/prepare.c), an object structure
 * built on demand, vertex updates and deletion.
 */
#include <rt/rt.h>
#include <stdio.h>
#include <string.h>

#include "base/mat4.h"
#include "check.h"
#include "scene/accel.h"
#include "scene/list.h"
#include "scene/recording.h"
#include "scene/scene.h"


/* Records one triangle strip quad into rec (as rtBegin(RT_TRIANGLE_STRIP)
 * with four rtVertex3f calls would) and returns its status. */
static enum scene_record_status record_quad(struct scene_recording *rec, float z)
{
    static const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    double identity[16];
    mat4_identity(identity);
    struct scene_block block;
    memset(&block, 0, sizeof(block));
    scene_block_start(&block, rec, RT_TRIANGLE_STRIP, identity);
    struct scene_material material;
    scene_material_default(&material);
    struct scene_triangle_state ts = {&material, 0, 0, 0};
    const float normal[3] = {0, 0, 1}, color[4] = {1, 1, 1, 1}, texcoord[4] = {0, 0, 0, 1};
    for (int i = 0; i < 4; i++) {
        double p[3] = {corners[i][0], corners[i][1], corners[i][2] + z};
        enum scene_record_status s =
            scene_record_vertex(rec, &block, &ts, p, normal, color, texcoord);
        if (s != SCENE_RECORD_OK)
            return s;
    }
    return SCENE_RECORD_OK;
}

/* The wide layout is made only when the kernels walk it: a context
 * with isa=scalar sets wide_layout to 0 (api/context.c), and then no
 * build spends time or memory on it; the binary tree is the same.  An
 * AVX2 context sets 8 and gets the 8-wide layout, others 4 (the default
 * 1 means 4); the collapse and the wide refit are timed. */
static void check_wide_layout_only_when_walked(void)
{
    static const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                      0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
    static const uint32_t indices[] = {0, 1, 2, 1, 3, 2, 4, 5, 6, 5, 7, 6};
    const struct scene_accel_geometry g = {positions, indices, 4};
    struct bvh_build_params params;
    bvh_build_params_default(&params);
    params.max_leaf_size = 1;
    CHECK(params.wide_layout == 1);
    struct scene_accel *with = scene_accel_build(&g, &params, SCENE_ACCEL_SERIAL, NULL, NULL);
    params.wide_layout = 0;
    struct scene_accel *without = scene_accel_build(&g, &params, SCENE_ACCEL_SERIAL, NULL, NULL);
    CHECK(with && without);
    if (with && without) {
        CHECK(with->wide.node_count > 0 && with->wide.nodes != NULL);
        CHECK(without->wide.node_count == 0 && without->wide.nodes == NULL);
        CHECK(with->bvh.node_count == without->bvh.node_count &&
              memcmp(with->bvh.nodes, without->bvh.nodes,
                     with->bvh.node_count * sizeof(*with->bvh.nodes)) == 0);
        /* A refit of the binary-only structure leaves it binary-only. */
        scene_accel_refit(without, &g, &params, NULL);
        CHECK(without->wide.node_count == 0);
        CHECK(with->wide.width == 4 && with->wide.nodes8 == NULL && with->collapse_ms >= 0.0);
        CHECK(with->wide.packet_count > 0 && with->wide.packets != NULL);
    }
    params.wide_layout = 8;
    struct scene_accel *eight = scene_accel_build(&g, &params, SCENE_ACCEL_SERIAL, NULL, NULL);
    CHECK(eight != NULL);
    if (eight) {
        CHECK(eight->wide.width == 8 && eight->wide.nodes8 != NULL && eight->wide.nodes == NULL);
        CHECK(((uintptr_t)eight->wide.nodes8 & 63u) == 0);
        CHECK(eight->wide_refit_ms == 0.0);
        scene_accel_refit(eight, &g, &params, NULL);
        CHECK(eight->wide.width == 8 && eight->wide_refit_ms >= 0.0);
    }
    scene_accel_release(eight);
    scene_accel_release(with);
    scene_accel_release(without);
}

/* A display list recorded and committed without an API context (the MPI
 * replay seam, recording.h): a quad, a recorded translation that moves
 * the next quad, an absolute load that starts a segment of its own. */
static void check_list_without_context(struct scene *scene)
{
    struct scene_recording rec;
    memset(&rec, 0, sizeof(rec));
    CHECK(scene_list_begin(&rec, 9, RT_MODELVIEW) == 0);
    double t[16];
    mat4_identity(t);
    t[12] = 2.0;
    struct scene_block block;
    memset(&block, 0, sizeof(block));
    struct scene_material material;
    scene_material_default(&material);
    struct scene_triangle_state ts = {&material, 0, 0, 0};
    const float n[3] = {0, 0, 1}, c[4] = {1, 1, 1, 1}, st[4] = {0, 0, 0, 1};
    static const double tri[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int pass = 0; pass < 3; pass++) {
        if (pass == 1)
            CHECK(scene_list_matrix_op(&rec, SCENE_OP_MULT, 0, t) == 0);
        if (pass == 2)
            CHECK(scene_list_matrix_op(&rec, SCENE_OP_LOAD, 0, t) == 0);
        scene_block_start(&block, &rec, RT_TRIANGLES, scene_list_matrix(&rec));
        for (int v = 0; v < 3; v++)
            CHECK(scene_record_vertex(&rec, &block, &ts, tri[v], n, c, st) == SCENE_RECORD_OK);
    }
    struct scene_mesh *meshes = NULL;
    struct scene_list_op *ops = NULL;
    uint32_t count = 0, op_count = 0;
    CHECK(scene_list_finish(&rec, &meshes, &count, &ops, &op_count, NULL) == 0);
    CHECK(count == 2);
    CHECK(meshes && meshes[0].tri_count == 2 && meshes[0].positions[3 * 3] == 2.0f);
    /* segment 0, mult, load, segment 1 */
    CHECK(op_count == 4 && ops[0].kind == SCENE_OP_SEGMENT && ops[3].kind == SCENE_OP_SEGMENT &&
          ops[3].a == 1);
    struct scene_object *object = scene_objects_get_or_create(&scene->objects, 9);
    CHECK(object && scene_define_list(scene, object, meshes, count, ops, op_count) == 0);
    CHECK(object && object->segment_count == 1 && object->op_count == 4);
    scene_list_release(&rec);
    scene_mesh_release(&rec.mesh);
}

int main(void)
{
    struct bvh_build_params params;
    bvh_build_params_default(&params);
    struct scene scene;
    scene_init(&scene, &params, 0, 0);

    /* Record and define object 7. */
    struct scene_recording rec;
    memset(&rec, 0, sizeof(rec));
    rec.material_index = -1;
    CHECK(record_quad(&rec, 0.0f) == SCENE_RECORD_OK);
    CHECK(rec.mesh.vertex_count == 4 && rec.mesh.tri_count == 2);
    scene_mesh_compute_bounds(&rec.mesh);
    struct scene_object *object = scene_objects_get_or_create(&scene.objects, 7);
    CHECK(object != NULL);
    if (!object)
        return 1;
    scene_define_object(&scene, object, &rec.mesh);
    {
        struct scene lists; /* a scene of its own: the change set below is counted */
        scene_init(&lists, &params, 0, 0);
        check_list_without_context(&lists);
        scene_release(&lists);
    }

    /* A non-finite vertex is refused without storing anything. */
    {
        struct scene_recording bad;
        memset(&bad, 0, sizeof(bad));
        bad.material_index = -1;
        double m[16];
        mat4_identity(m);
        m[0] = 1e300;
        struct scene_block block;
        memset(&block, 0, sizeof(block));
        scene_block_start(&block, &bad, RT_TRIANGLES, m);
        struct scene_material material;
        scene_material_default(&material);
        struct scene_triangle_state ts = {&material, 0, 0, 0};
        const double p[3] = {1, 0, 0};
        const float n[3] = {0, 0, 1}, c[4] = {1, 1, 1, 1}, t[4] = {0, 0, 0, 1};
        CHECK(!scene_block_vertex_is_finite(&block, p));
        CHECK(scene_record_vertex(&bad, &block, &ts, p, n, c, t) == SCENE_RECORD_NOT_FINITE);
        CHECK(bad.mesh.vertex_count == 0);
        scene_mesh_release(&bad.mesh);
    }

    /* One instance at the origin. */
    double identity[16];
    mat4_identity(identity);
    CHECK(scene_frame_add_instance(&scene.frame, object, identity, identity, identity) == 0);
    struct scene_changes changes;
    CHECK(scene_prepare_toplevel(&scene) == SCENE_OK);
    CHECK(scene_prepare_objects(&scene, NULL, 100.0, &changes) == SCENE_OK);
    CHECK(changes.defined == 1 && changes.redefined == 0 && changes.moved == 1);
    CHECK(changes.toplevel_rebuilt == 1 && changes.updated == 0);
    CHECK(scene.stats.toplevel_builds == 1);
    CHECK(scene.frame.top_valid && scene.frame.trace_instance_count == 1);

    /* The structure is built on demand, as a render thread would. */
    int built = 0;
    const struct scene_accel *accel =
        scene_object_acquire(object, &scene.update_config, &built);
    CHECK(accel != NULL && built == 1 && accel->bvh.prim_count == 2);
    CHECK(scene_object_peek(object) == accel);
    scene_end_frame(&scene, 1000, 0, 0.0);

    /* The same frame again: nothing changed, nothing is rebuilt. */
    CHECK(scene_frame_add_instance(&scene.frame, object, identity, identity, identity) == 0);
    CHECK(scene_prepare_toplevel(&scene) == SCENE_OK);
    CHECK(scene_prepare_objects(&scene, NULL, 100.0, &changes) == SCENE_OK);
    CHECK(changes.defined == 0 && changes.moved == 0 && changes.touched == 0);
    CHECK(changes.toplevel_rebuilt == 0 && scene.stats.toplevel_builds == 0);
    scene_end_frame(&scene, 1000, 0, 0.0);

    /* Moving vertices makes the structure stale; preparation updates it. */
    const float lifted[6] = {0, 0, 2, 1, 0, 2};
    scene_update_vertices(&scene, object, 0, 0, 2, lifted, 0, 3 * sizeof(float));
    CHECK(object->mesh.positions[2] == 2.0f && object->mesh.bounds.max[2] == 2.0f);
    CHECK(scene_frame_add_instance(&scene.frame, object, identity, identity, identity) == 0);
    CHECK(scene_prepare_toplevel(&scene) == SCENE_OK);
    CHECK(scene_prepare_objects(&scene, NULL, 100.0, &changes) == SCENE_OK);
    CHECK(changes.touched == 1 && changes.updated == 1);
    CHECK(scene.stats.object_updates == 1);
    accel = scene_object_peek(object);
    CHECK(accel && accel->serial == object->serial);
    scene_end_frame(&scene, 1000, 0, 0.0);

    /* Redefinition and deletion are part of the change set too. */
    memset(&rec, 0, sizeof(rec));
    rec.material_index = -1;
    CHECK(record_quad(&rec, 5.0f) == SCENE_RECORD_OK);
    scene_mesh_compute_bounds(&rec.mesh);
    scene_define_object(&scene, object, &rec.mesh);
    scene_delete_object(&scene, 7);
    scene_delete_object(&scene, 8); /* unknown: ignored */
    CHECK(scene_objects_lookup(&scene.objects, 7) == NULL);
    CHECK(scene_prepare_toplevel(&scene) == SCENE_OK);
    CHECK(scene_prepare_objects(&scene, NULL, 100.0, &changes) == SCENE_OK);
    CHECK(changes.redefined == 1 && changes.deleted == 1);

    scene_mesh_release(&rec.mesh);
    scene_release(&scene);
    check_wide_layout_only_when_walked();
    return test_summary("scene_standalone");
}
