/* SPDX-License-Identifier: Apache-2.0 */
/*
 * shade_eye_unit.h - the external names of shade.c, surface.c and
 * scene/texture.c with SHADE_EYE_SUFFIX appended (_avx2, _avx512), for
 * the units that compile those files again for one instruction set
 * (shade_eye_avx2.c, shade_eye_avx512.c).  One list, so that a function
 * added to those files is renamed in every copy.  A unit defines
 * SHADE_EYE_SUFFIX, includes this, then the three sources.
 *
 * Each name's own macro does not expand inside its replacement (C99
 * 6.10.3.4), so SHADE_EYE_NAME receives the name itself and pastes the
 * suffix to it.
 */
#ifndef RT_RENDER_SHADE_EYE_UNIT_H
#define RT_RENDER_SHADE_EYE_UNIT_H

#define SHADE_EYE_PASTE_(name, suffix) name##suffix
#define SHADE_EYE_PASTE(name, suffix) SHADE_EYE_PASTE_(name, suffix)
#define SHADE_EYE_NAME(name) SHADE_EYE_PASTE(name, SHADE_EYE_SUFFIX)

#define shade_context_lights SHADE_EYE_NAME(shade_context_lights)
#define shade_eye_hits SHADE_EYE_NAME(shade_eye_hits)
#define shade_eye_block_begin SHADE_EYE_NAME(shade_eye_block_begin)
#define shade_eye_block_end SHADE_EYE_NAME(shade_eye_block_end)
#define shade_hit SHADE_EYE_NAME(shade_hit)
#define shade_offset_point SHADE_EYE_NAME(shade_offset_point)
#define shade_prime_shadows SHADE_EYE_NAME(shade_prime_shadows)
#define shade_ray SHADE_EYE_NAME(shade_ray)
#define surface_fetch SHADE_EYE_NAME(surface_fetch)
#define surface_fetch_colour SHADE_EYE_NAME(surface_fetch_colour)
#define surface_fetch_colours SHADE_EYE_NAME(surface_fetch_colours)
#define surface_fetches SHADE_EYE_NAME(surface_fetches)
#define surface_fetch_lanes SHADE_EYE_NAME(surface_fetch_lanes)
#define surface_resolve_material SHADE_EYE_NAME(surface_resolve_material)
#define surface_texel SHADE_EYE_NAME(surface_texel)
#define scene_texture_build_mipmaps SHADE_EYE_NAME(scene_texture_build_mipmaps)
#define scene_texture_chain_texels SHADE_EYE_NAME(scene_texture_chain_texels)
#define scene_texture_level_count SHADE_EYE_NAME(scene_texture_level_count)
#define scene_texture_sample SHADE_EYE_NAME(scene_texture_sample)
#define scene_texture_sample_level SHADE_EYE_NAME(scene_texture_sample_level)
#define scene_texture_sample_lod SHADE_EYE_NAME(scene_texture_sample_lod)
#define scene_texture_sample_lod8 SHADE_EYE_NAME(scene_texture_sample_lod8)
#define scene_texture_prefetch_lod8 SHADE_EYE_NAME(scene_texture_prefetch_lod8)
#define scene_texture_finish_lod8 SHADE_EYE_NAME(scene_texture_finish_lod8)
#define scene_texture_set_image SHADE_EYE_NAME(scene_texture_set_image)
#define scene_textures_generate SHADE_EYE_NAME(scene_textures_generate)
#define scene_textures_get_or_create SHADE_EYE_NAME(scene_textures_get_or_create)
#define scene_textures_init SHADE_EYE_NAME(scene_textures_init)
#define scene_textures_lookup SHADE_EYE_NAME(scene_textures_lookup)
#define scene_textures_release SHADE_EYE_NAME(scene_textures_release)
#define scene_textures_remove SHADE_EYE_NAME(scene_textures_remove)

#endif
