#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# check_header_only.sh PROGRAM.c ...: the GL build and the Tracelist build
# of each program differ only in the headers it includes.  USE_TRACELIST
# must appear in exactly one #ifdef, whose two branches hold nothing but
# #include lines, and nowhere else.
status=0
for f in "$@"; do
    uses=$(grep -c USE_TRACELIST "$f")
    block=$(awk '
        /^#ifdef USE_TRACELIST$/ { inside = 1; next }
        inside && /^#endif/ { inside = 0; next }
        inside && !/^#include </ && !/^#else$/ { print "not an #include: " $0 }
    ' "$f")
    if [ "$uses" -ne 1 ] || ! grep -q '^#ifdef USE_TRACELIST$' "$f" || [ -n "$block" ]; then
        echo "$f: the builds differ in more than the included headers ($uses uses) $block"
        status=1
    else
        echo "$f: only the headers differ"
    fi
done
exit $status
