/* SPDX-License-Identifier: Apache-2.0 */
/* A trace header that reaches up into scene: check-includes.sh must refuse it. */
#include "scene/object.h"
