#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# run_compare.sh KIND OUTDIR NAME GL_EXE RT_EXE COMPARE_EXE [compare arguments]
#
# Runs a program's GL build and its Tracelist build (RT_EXE "-": the GL
# build alone, compared with itself, its image <name>-gl-alone.ppm) and
# compares the two images with compare_images.  KIND "offscreen": the image path is the program's
# argument; "glut": it is TRACELIST_OUT (the headless GLUT rules; the
# other TRACELIST_* variables come from the test's environment).  Fails
# when a build exits non-zero (an error was recorded), prints anything
# with "error" on stderr, or the comparison fails.
kind=$1 outdir=$2 name=$3 gl_exe=$4 rt_exe=$5 compare=$6
shift 6
mkdir -p "$outdir" || exit 1
run() { # run EXE IMAGE
    if [ "$kind" = glut ]; then
        TRACELIST_OUT=$2 TRACELIST_HEADLESS=1 "$1" 2>"$2.log"
    else
        "$1" "$2" 2>"$2.log"
    fi
    status=$?
    cat "$2.log" >&2
    if [ $status -ne 0 ] || grep -qi error "$2.log"; then
        echo "run_compare: $1 failed (status $status)" >&2
        return 1
    fi
}
# The GL build alone writes its own file: ctest runs a program's two
# tests at once under -j, and one shared GL image was rewritten by one
# test while the other read it ("cannot read <name>-gl.ppm").
if [ "$rt_exe" = - ]; then
    run "$gl_exe" "$outdir/$name-gl-alone.ppm" || exit 1
    exec "$compare" "$outdir/$name-gl-alone.ppm" "$outdir/$name-gl-alone.ppm" "$@"
fi
run "$gl_exe" "$outdir/$name-gl.ppm" || exit 1
run "$rt_exe" "$outdir/$name-rt.ppm" || exit 1
exec "$compare" "$outdir/$name-gl.ppm" "$outdir/$name-rt.ppm" --diff "$outdir/$name-diff.ppm" "$@"
