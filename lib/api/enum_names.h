/* SPDX-License-Identifier: Apache-2.0 */
/*
 * enum_names.h - public enums by name for error messages (enum_names.c).
 */
#ifndef RT_API_ENUM_NAMES_H
#define RT_API_ENUM_NAMES_H

#include <rt/rt.h>

#define RT_ENUM_STRING_SIZE 16

/* "RT_FOG" for RT_FOG; NULL for a value no public enum has. */
const char *rt_enum_name(RTenum value);
/* The name, or the value in hex written into buffer. */
const char *rt_enum_string(RTenum value, char buffer[RT_ENUM_STRING_SIZE]);

#endif
