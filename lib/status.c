/* SPDX-License-Identifier: MIT */
/*
 * The foundation floor: statuses and their messages, for every layer
 * (status.h). Nothing here knows any layer above it.
 */
#include "config.h"

#include <stdarg.h>
#include <stdio.h>

#include <noctree/status.h>

#include "internal.h"

noctStatus noct_fail(noctError *err, noctStatus status, long index, long line,
                     const char *fmt, ...)
{
    if (err != NULL) {
        err->status = status;
        err->index = index;
        err->line = line;
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
    }
    return status;
}

const char *noctStatusString(noctStatus status)
{
    static const char *const text[NOCT_STATUS_COUNT] = {
        [NOCT_OK] = "success",
        [NOCT_ERR_NOMEM] = "out of memory",
        [NOCT_ERR_INVALID] = "invalid argument",
        [NOCT_ERR_NONFINITE] = "value is NaN or infinite",
        [NOCT_ERR_TOO_LARGE] = "too large",
        [NOCT_ERR_INDEX] = "vertex index out of range",
        [NOCT_ERR_DEGENERATE] = "degenerate polygon or mesh",
        [NOCT_ERR_NONPLANAR] = "polygon is not planar",
        [NOCT_ERR_NONCONVEX] = "polygon is not convex",
        [NOCT_ERR_OPEN] = "mesh is not closed",
        [NOCT_ERR_ORIENTATION] = "polygons are not consistently oriented",
        [NOCT_ERR_PARSE] = "syntax error",
        [NOCT_ERR_IO] = "input/output error",
        [NOCT_ERR_NUMERIC] = "numerical failure",
        [NOCT_ERR_INVARIANT] = "internal invariant broken",
    };
    if ((unsigned)status >= NOCT_STATUS_COUNT)
        return "unknown status";
    return text[status];
}
