/* SPDX-License-Identifier: Apache-2.0 */
/* overlay_oracle.h - the overlay scenes' two copies (overlay_scene.inc). */
#ifndef ORACLE_OVERLAY_ORACLE_H
#define ORACLE_OVERLAY_ORACLE_H

/* Largest bitmap of the scenes: 12 rows of 4 bytes. */
#define OVERLAY_BITMAP_BYTES (12 * 4)

/* Fills a width x height bitmap (rows of GL's 4-byte alignment) with a
 * pseudo-random pattern of its own seed, the same in both copies. */
void overlay_pattern(unsigned char *bits, int width, int height, unsigned seed);

#define OVERLAY_DECLARE(suffix)                                                                    \
    void overlay_shape_##suffix(void);                                                             \
    void overlay_panel_list_##suffix(void);                                                        \
    void overlay_panel_##suffix(void);                                                             \
    void overlay_crosshair_##suffix(void);                                                         \
    void overlay_depth_on_##suffix(void);                                                          \
    void overlay_background_##suffix(void);                                                        \
    void overlay_lit_##suffix(void);                                                               \
    void overlay_text_panel_##suffix(void);                                                        \
    void overlay_unpushed_##suffix(void);                                                          \
    void overlay_textured_##suffix(void);
OVERLAY_DECLARE(gl)
OVERLAY_DECLARE(rt)

#endif
