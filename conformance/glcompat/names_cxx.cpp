// SPDX-License-Identifier: Apache-2.0
// names_cxx.cpp - rt/glcompat.h and the GL-named program of names.c compile as C++.
#include "names.c"
