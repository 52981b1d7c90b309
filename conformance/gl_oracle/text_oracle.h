/* SPDX-License-Identifier: Apache-2.0 */
/* text_oracle.h - the text scene's two copies (text_scene.inc) and their
 * bitmaps. */
#ifndef ORACLE_TEXT_ORACLE_H
#define ORACLE_TEXT_ORACLE_H

/* Largest bitmap of the scene: 40 rows of 8 bytes. */
#define TEXT_MAX_BITMAP (40 * 8)

/* Fills a width x height bitmap (rows of GL's 4-byte alignment) with a
 * pseudo-random pattern of its own seed, the same in both copies. */
void text_pattern(unsigned char *bits, int width, int height, unsigned seed);

void text_projection_gl(void);
void text_view_gl(void);
void text_shape_gl(void);
void text_overlay_gl(void);
void text_projection_rt(void);
void text_view_rt(void);
void text_shape_rt(void);
void text_overlay_rt(void);

#endif
