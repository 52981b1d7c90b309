/* SPDX-License-Identifier: Apache-2.0 */
/* rtu reaching into the core: check-includes.sh must refuse it. */
#include "base/mat4.h"
