#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# check_names.sh GL_H GLU_H GLUT_H GLCOMPAT_H: every GL 1.0/1.1 name of
# the system's gl.h (functions and enums before its "OpenGL 1.2" part),
# every GLU name of glu.h and every GLUT 3 name of glut.h is defined by
# rt/glcompat.h (mapped, adapted, no-op, pending or absent).  Prints the
# missing names and fails when there is one.
gl_h=$1 glu_h=$2 glut_h=$3 compat=$4
names=$(
    {
        sed -n '1,/OpenGL 1\.2/p' "$gl_h" | grep -oE '\bgl[A-Z][A-Za-z0-9]*[ ]*\(' | tr -d ' ('
        sed -n '1,/OpenGL 1\.2/p' "$gl_h" | grep -oE '^#define[ 	]+GL_[A-Z0-9_]+[ 	]+(0x[0-9A-Fa-f]+|[0-9]+)' |
            awk '{print $2}' | grep -v -e '^GL_VERSION_1_[23]$' -e '^GL_ARB_'
        grep -oE '\bglu[A-Z][A-Za-z0-9]*[ ]*\(' "$glu_h" | tr -d ' ('
        grep -oE '^#define[ 	]+GLU_[A-Z0-9_]+' "$glu_h" | awk '{print $2}' | grep -v -e '^GLU_VERSION_1_' -e '^GLU_EXT_'
        grep -oE '\bglut[A-Z][A-Za-z0-9]*[ ]*\(' "$glut_h" | tr -d ' ('
    } | sort -u
)
defined=$(grep -oE '^#define [A-Za-z0-9_]+' "$compat" | awk '{print $2}' | sort -u)
missing_names=$(printf '%s\n' "$names" | grep -vxF -e "$(printf '%s\n' "$defined")")
checked=$(printf '%s\n' "$names" | grep -c .)
missing=$(printf '%s\n' "$missing_names" | grep -c .)
[ "$missing" -gt 0 ] && printf 'not in glcompat.h: %s\n' $missing_names
echo "glcompat/names_complete: $checked names checked, $missing missing"
[ "$checked" -gt 500 ] && [ "$missing" -eq 0 ]
