/* SPDX-License-Identifier: Apache-2.0 */
/*
 * render_unit.h - the external names of render.c with RENDER_SUFFIX
 * appended (_avx2, _avx512), for the units that compile it again for one
 * instruction set (render_avx2.c, render_avx512.c).  One list, so that a
 * function added to render.c is renamed in every copy.  A unit defines
 * RENDER_SUFFIX, includes this, then render.c.
 *
 * Each name's own macro does not expand inside its replacement (C99
 * 6.10.3.4), so RENDER_UNIT_NAME receives the name itself and pastes the
 * suffix to it.
 */
#ifndef RT_RENDER_RENDER_UNIT_H
#define RT_RENDER_RENDER_UNIT_H

#define RENDER_UNIT_PASTE_(name, suffix) name##suffix
#define RENDER_UNIT_PASTE(name, suffix) RENDER_UNIT_PASTE_(name, suffix)
#define RENDER_UNIT_NAME(name) RENDER_UNIT_PASTE(name, RENDER_SUFFIX)

#define render_framebuffer_release RENDER_UNIT_NAME(render_framebuffer_release)
#define render_pass_begin RENDER_UNIT_NAME(render_pass_begin)
#define render_pass_tiles RENDER_UNIT_NAME(render_pass_tiles)
#define render_tile RENDER_UNIT_NAME(render_tile)
#define render_pass_raster RENDER_UNIT_NAME(render_pass_raster)
#define render_pass_end RENDER_UNIT_NAME(render_pass_end)
#define render_frame RENDER_UNIT_NAME(render_frame)
#define render_trace_rays RENDER_UNIT_NAME(render_trace_rays)
#define render_occluded_rays RENDER_UNIT_NAME(render_occluded_rays)
#define render_unproject_rows RENDER_UNIT_NAME(render_unproject_rows)

#endif
