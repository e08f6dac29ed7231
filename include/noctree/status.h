/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/status.h
 * @brief Status codes and error details of the collision API.
 *
 * @defgroup noctree_status Status codes
 * @brief How the library reports bad input and failures.
 *
 * Functions that can fail for reasons other than a programming error (bad
 * data in a file or from a caller, running out of memory) return a
 * #noctStatus and, if the caller passes a #noctError, fill it with where
 * and what the problem is. They never print and never exit. Only a violated
 * precondition (`@pre`) aborts, and only in the defensive build.
 * @{
 */
#ifndef NOCTREE_STATUS_H
#define NOCTREE_STATUS_H

#include <noctree/export.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @brief The outcome of an operation that can fail. */
typedef enum noctStatus {
    NOCT_OK = 0,          /**< Success. */
    NOCT_ERR_NOMEM,       /**< Memory could not be allocated. */
    NOCT_ERR_INVALID,     /**< An argument is out of its documented range. */
    NOCT_ERR_NONFINITE,   /**< A coordinate or value is NaN or infinite. */
    NOCT_ERR_TOO_LARGE,   /**< A count or size exceeds the library's limits. */
    NOCT_ERR_INDEX,       /**< A polygon names a vertex that does not exist. */
    NOCT_ERR_DEGENERATE,  /**< A polygon or mesh has no area or volume. */
    NOCT_ERR_NONPLANAR,   /**< A polygon's vertices are not coplanar. */
    NOCT_ERR_NONCONVEX,   /**< A polygon is not convex. */
    NOCT_ERR_OPEN,        /**< An edge is not shared by exactly two polygons. */
    NOCT_ERR_ORIENTATION, /**< Two polygons orient their shared edge alike. */
    NOCT_ERR_PARSE,       /**< A file does not follow its format. */
    NOCT_ERR_IO,          /**< A file could not be opened or read. */
    NOCT_ERR_NUMERIC,     /**< A numerical method failed (see the message). */
    NOCT_ERR_INVARIANT,   /**< A validation walk found a structure broken: a
                               bug in the library, or memory the program
                               overwrote. Only the validation functions
                               return it. */
    NOCT_STATUS_COUNT     /**< Number of status codes; not a status. */
} noctStatus;

/** Length of #noctError::message, including the terminating NUL. */
#define NOCT_ERROR_MESSAGE_SIZE 256

/**
 * @brief Where and what went wrong, filled by a failing operation.
 *
 * Pass a pointer to one wherever a function takes `noctError *err`, or
 * NULL if the status code is enough.
 */
typedef struct noctError {
    noctStatus status; /**< The status the operation returned. */
    long index;        /**< Index of the offending vertex, polygon or edge
                            (see the message), or -1. */
    long line;         /**< Line of the offending file, or 0. */
    /** One line of text naming the file and line if any and the problem,
     *  such as `cube.off:12: polygon 3: vertex index 9 out of range`. */
    char message[NOCT_ERROR_MESSAGE_SIZE];
} noctError;

/**
 * @brief Return a short description of a status code.
 * @param[in] status A status code.
 * @post The result is a static, non-empty English phrase; for a value that
 *       is not a #noctStatus it is "unknown status".
 * @return The description.
 */
NOCT_API const char *noctStatusString(noctStatus status);

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_STATUS_H */
