/* SPDX-License-Identifier: Apache-2.0 */
// Compiled as C++ with -pedantic-errors: the public headers are valid C++.
#include <rt/rt.h>
#include <rt/rtu.h>

int header_cxx_probe();
int header_cxx_probe()
{
    RThit hit = {0, 0, 0, RT_INVALID_ID, RT_INVALID_ID, RT_INVALID_ID};
    return static_cast<int>(hit.t);
}
