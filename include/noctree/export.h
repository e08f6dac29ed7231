/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/export.h
 * @brief The export macro that marks libnoctree's public API.
 *
 * The library is compiled with hidden symbol visibility; only declarations
 * marked with `NOCT_API` are exported from the shared objects, so
 * `nm -D libnoctree.so` lists exactly the documented API.
 */
#ifndef NOCTREE_EXPORT_H
#define NOCTREE_EXPORT_H

#if defined(__GNUC__) || defined(__clang__)
/** Marks a function as part of the exported, documented API. */
#  define NOCT_API __attribute__((visibility("default")))
#else
#  define NOCT_API
#endif

#endif /* NOCTREE_EXPORT_H */
