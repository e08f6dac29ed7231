/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/octree.h
 * @brief The octree abstract data type: nodes, directions and their operations.
 *
 * @defgroup noctree_octree Octree ADT
 * @brief The report's octree abstract data type (octree.h).
 *
 * An octree node (#octNode) is an opaque handle. A root is made with
 * octCreate(); octSplit() gives a leaf its eight children, which are
 * allocated together in one block; octJoin() removes every descendant again.
 * Each node carries one pointer of client data (octData(), octSwapData()).
 *
 * **Directions.** An #octDirection names one of the 26 directions of a cube
 * (6 faces, 12 edges, 8 vertices, after Samet) or #OCT_OMEGA. The eight
 * vertex directions double as the child types of a node's children.
 * Geometrically the library uses a right-handed frame: L/R is -x/+x,
 * D/U is -y/+y and B/F is -z/+z (F faces a viewer looking down -z).
 *
 * **Two builds.** The *defensive* library (pkg-config module `noctree`, the
 * default) checks every *requires* clause (`@pre`) with assert(3) and aborts
 * when one is violated: a violation is a programming error. The *efficient*
 * library (module `noctree-efficient`, compiled with `NDEBUG`) checks
 * nothing; a client compiled with `NOCT_EFFICIENT` or `NDEBUG` also gets
 * octParent(), octChild(), octChildType(), octIsSplit(), octGeneration(),
 * octData() and octSwapData() as `static inline` functions. Violating a
 * precondition against the efficient build is undefined behaviour.
 *
 * **Errors.** Running out of memory is not a programming error: octCreate()
 * returns NULL and octSplit() returns false, in both builds, leaving the tree
 * as it was. The library never prints except in octPrint() and never exits.
 * @{
 */
#ifndef NOCTREE_OCTREE_H
#define NOCTREE_OCTREE_H

#include <stdbool.h>
#include <stdio.h>

#include <noctree/export.h>

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief A direction in the octree sense: a face, an edge or a vertex of a
 * cube, or the undefined direction.
 *
 * The order is the report's (Figure 1). Faces come first (#OCT_L .. #OCT_F),
 * then the 12 edges (#OCT_LD .. #OCT_UF), then the 8 vertices
 * (#OCT_LDB .. #OCT_RUF), then #OCT_OMEGA. A vertex direction's offset from
 * #OCT_LDB has bit 2 set for R, bit 1 for U and bit 0 for F.
 *
 * A client that defines `OCT_SHORT_NAMES` before including this header also
 * gets the report's unprefixed names (`L`, `R`, ..., `RUF`, `OMEGA`) as
 * further members of this enumeration. They are off by default because
 * names such as `L` and `B` easily clash with a client's own.
 */
typedef enum octDirection {
    OCT_L,   /**< Left face (-x). */
    OCT_R,   /**< Right face (+x). */
    OCT_D,   /**< Down face (-y). */
    OCT_U,   /**< Up face (+y). */
    OCT_B,   /**< Back face (-z). */
    OCT_F,   /**< Front face (+z). */
    OCT_LD,  /**< Left-down edge. */
    OCT_LU,  /**< Left-up edge. */
    OCT_LB,  /**< Left-back edge. */
    OCT_LF,  /**< Left-front edge. */
    OCT_RD,  /**< Right-down edge. */
    OCT_RU,  /**< Right-up edge. */
    OCT_RB,  /**< Right-back edge. */
    OCT_RF,  /**< Right-front edge. */
    OCT_DB,  /**< Down-back edge. */
    OCT_DF,  /**< Down-front edge. */
    OCT_UB,  /**< Up-back edge. */
    OCT_UF,  /**< Up-front edge. */
    OCT_LDB, /**< Left-down-back vertex (child type). */
    OCT_LDF, /**< Left-down-front vertex (child type). */
    OCT_LUB, /**< Left-up-back vertex (child type). */
    OCT_LUF, /**< Left-up-front vertex (child type). */
    OCT_RDB, /**< Right-down-back vertex (child type). */
    OCT_RDF, /**< Right-down-front vertex (child type). */
    OCT_RUB, /**< Right-up-back vertex (child type). */
    OCT_RUF, /**< Right-up-front vertex (child type). */
    OCT_OMEGA /**< The undefined direction (Samet's Omega). */
#if defined(OCT_SHORT_NAMES) && !defined(NOCT_DOXYGEN)
    , L = OCT_L, R = OCT_R, D = OCT_D, U = OCT_U, B = OCT_B, F = OCT_F,
    LD = OCT_LD, LU = OCT_LU, LB = OCT_LB, LF = OCT_LF,
    RD = OCT_RD, RU = OCT_RU, RB = OCT_RB, RF = OCT_RF,
    DB = OCT_DB, DF = OCT_DF, UB = OCT_UB, UF = OCT_UF,
    LDB = OCT_LDB, LDF = OCT_LDF, LUB = OCT_LUB, LUF = OCT_LUF,
    RDB = OCT_RDB, RDF = OCT_RDF, RUB = OCT_RUB, RUF = OCT_RUF,
    OMEGA = OCT_OMEGA
#endif
} octDirection;

/** Number of defined directions (faces, edges and vertices), 26. */
#define OCT_NUM_DIRECTIONS 26

/** True iff @p d is one of the six face directions. */
#define OCT_IS_FACE(d) ((unsigned)(d) <= (unsigned)OCT_F)
/** True iff @p d is one of the twelve edge directions. */
#define OCT_IS_EDGE(d) \
    ((unsigned)(d) - (unsigned)OCT_LD <= (unsigned)(OCT_UF - OCT_LD))
/** True iff @p d is one of the eight vertex directions (a child type). */
#define OCT_IS_VERTEX(d) \
    ((unsigned)(d) - (unsigned)OCT_LDB <= (unsigned)(OCT_RUF - OCT_LDB))


/**
 * @brief An octree node; opaque.
 *
 * Clients use only pointers to it and the operations of this module. (The
 * efficient build's inline accessors see its layout; that layout is private
 * and may only change with a new SONAME.)
 */
typedef struct octNode octNode;

/**
 * @brief Client-supplied disposer of the data stored at a node (the
 * report's ItemDisposer).
 * @param[in] data The client data to dispose; never NULL when the library
 *                 calls it.
 * @pre @p data accesses a client data structure.
 * @post @p data is disposed; any memory it owned is returned.
 */
typedef void octItemDisposer(void *data);

/**
 * @brief Client-supplied printer of the data stored at a node (the report's
 * ItemPrinter).
 * @param[in] strm An open stream to print to.
 * @param[in] data The client data to print; never NULL when the library
 *                 calls it.
 * @pre @p strm is an open FILE*, @p data accesses a client data structure.
 * @post A textual representation of @p data is printed to @p strm, on one
 *       line without a trailing newline.
 */
typedef void octItemPrinter(FILE *strm, const void *data);

/* In the efficient flavour the accessors are static inline functions whose
 * definitions follow at the end of this header; otherwise they are exported
 * functions of the library. The library itself always builds them out of
 * line, so that both shared objects export the same symbols. */
#if (defined(NOCT_EFFICIENT) || defined(NDEBUG)) && !defined(NOCT_BUILDING) \
    && !defined(NOCT_DOXYGEN)
#  define NOCT_INLINE_ACCESSORS 1
#  define NOCT_ACCESSOR static inline
#else
/** 1 when the accessors are the efficient flavour's inline functions. */
#  define NOCT_INLINE_ACCESSORS 0
/** How the accessors are declared: exported, or static inline. */
#  define NOCT_ACCESSOR NOCT_API
#endif

/* ---------------------------------------------------------------------- */
/** @name Primary operations
 * @{ */

/**
 * @brief Create a new root node.
 * @return A new root: a leaf with no parent, generation 0, child type
 *         #OCT_OMEGA and NULL data; or NULL if memory ran out.
 * @post The result, if not NULL, is a root node and a leaf.
 */
NOCT_API octNode *octCreate(void);

/**
 * @brief Recursively dispose of the octree rooted at @p N.
 * @param[in] N The root of the tree to dispose.
 * @pre @p N is not NULL and octParent(N) == NULL.
 * @pre The octree rooted at @p N is empty of client data (see octClear()).
 * @post The octree rooted at @p N is disposed: @p N and every node below it
 *       are freed.
 */
NOCT_API void octDispose(octNode *N);

/**
 * @brief Recursively remove the client data from the subtree rooted at @p N.
 * @param[in] N    The subtree's top node (any node).
 * @param[in] kill The disposer called on each datum, or NULL.
 * @pre @p N is not NULL.
 * @pre @p kill != NULL or the subtree rooted at @p N is empty of client data
 *      (this clause is ours: it makes a forgotten disposer an error rather
 *      than a silent leak).
 * @post @p kill has been called once on every non-NULL datum in the subtree,
 *       @p N's own included, and every node of the subtree has NULL data.
 *       The shape of the tree is unchanged.
 */
NOCT_API void octClear(octNode *N, octItemDisposer *kill);

/**
 * @brief Return the parent of @p N.
 * @param[in] N A node.
 * @pre @p N is not NULL.
 * @post octParent(N) is N's parent, or NULL if @p N is a root.
 * @return The parent node, or NULL.
 */
NOCT_ACCESSOR octNode *octParent(const octNode *N);

/**
 * @brief Return the @p O child of @p N.
 * @param[in] N A node.
 * @param[in] O A vertex direction naming the child.
 * @pre @p N is not NULL.
 * @pre @p O is a vertex (#OCT_LDB .. #OCT_RUF).
 * @post octChild(N, O) is N's O child, or NULL if @p N is a leaf.
 * @return The child, or NULL.
 */
NOCT_ACCESSOR octNode *octChild(const octNode *N, octDirection O);

/**
 * @brief Return the child type of @p N in octParent(N).
 * @param[in] N A node.
 * @pre @p N is not NULL.
 * @post If @p N is a root, the result is #OCT_OMEGA; otherwise it is the
 *       vertex direction of @p N within its parent.
 * @return A vertex direction or #OCT_OMEGA.
 */
NOCT_ACCESSOR octDirection octChildType(const octNode *N);

/**
 * @brief Tell whether @p N is an internal node or a leaf.
 * @param[in] N A node.
 * @pre @p N is not NULL.
 * @post The result is true if @p N is an internal node (it has children)
 *       and false if it is a leaf.
 * @return Whether @p N is split.
 */
NOCT_ACCESSOR bool octIsSplit(const octNode *N);

/**
 * @brief Split a leaf node, giving it eight children.
 * @param[in] N A leaf.
 * @pre @p N is not NULL.
 * @pre octIsSplit(N) == false.
 * @post On success octIsSplit(N) == true; @p N has eight leaf children of
 *       generation octGeneration(N) + 1 with NULL data, allocated together;
 *       @p N's own datum is unchanged.
 * @return true on success; false if memory ran out, in which case @p N is
 *         unchanged and still a leaf.
 */
NOCT_API bool octSplit(octNode *N);

/**
 * @brief Unsplit an internal node, removing all of its descendants.
 * @param[in] N    An internal node.
 * @param[in] kill The disposer called on each datum removed, or NULL.
 * @pre @p N is not NULL.
 * @pre octIsSplit(N) == true.
 * @pre @p kill != NULL or every descendant of @p N has NULL data.
 * @post octIsSplit(N) == false. Every descendant of @p N (not only the
 *       children) is freed, after @p kill was called once on each non-NULL
 *       datum among them. @p N's own datum is kept.
 */
NOCT_API void octJoin(octNode *N, octItemDisposer *kill);

/**
 * @brief Return the generation (level) of @p N.
 * @param[in] N A node.
 * @pre @p N is not NULL.
 * @post The result is the generation of @p N: 0 for a root, 1 for the
 *       root's children, 2 for theirs, and so on.
 * @return The generation, at least 0.
 */
NOCT_ACCESSOR int octGeneration(const octNode *N);

/**
 * @brief Access the client data at node @p N.
 * @param[in] N A node.
 * @pre @p N is not NULL.
 * @post The result is the client data pointer stored at @p N.
 * @return The stored pointer; NULL for a node that holds none.
 */
NOCT_ACCESSOR void *octData(const octNode *N);

/**
 * @brief Swap the client data at node @p N.
 * @param[in] N       A node.
 * @param[in] newData The pointer to store at @p N (may be NULL).
 * @pre @p N is not NULL.
 * @post octData(N) == newData.
 * @return The pointer that was stored at @p N before the call.
 */
NOCT_ACCESSOR void *octSwapData(octNode *N, void *newData);

/**
 * @brief Initialize the child iterator of @p N1.
 *
 * The iterator's state lives in the node, so iterations over different
 * nodes may be nested; restarting it on the same node starts over.
 * @param[in] N1 An internal node.
 * @pre @p N1 is not NULL.
 * @pre octIsSplit(N1) == true.
 * @post An iterator is initialized that visits every child of @p N1 once,
 *       in vertex order #OCT_LDB .. #OCT_RUF.
 */
NOCT_API void octInitChildIterator(octNode *N1);

/**
 * @brief Return the next child of @p N1.
 * @param[in]  N1 The node whose children are iterated.
 * @param[out] N2 Receives the next child.
 * @pre @p N1 and @p N2 are not NULL.
 * @pre octInitChildIterator(N1) has been called since @p N1 was last split
 *      or joined.
 * @post The result is true and @p *N2 is a child of @p N1 not visited since
 *       the iterator was initialized; or the result is false, all children
 *       have been visited and @p *N2 is unchanged.
 * @return Whether a child was returned.
 */
NOCT_API bool octNextChild(octNode *N1, octNode **N2);

/**
 * @brief Print the subtree rooted at @p N.
 *
 * One line per node, in depth-first order (children in vertex order),
 * indented by two spaces per generation below @p N: the node's child type
 * (octDirToStr(), `OMEGA` for a root), its generation, and, if the node
 * holds data and @p prnt is not NULL, a colon, a space and @p prnt's text.
 * For example `  LDB 1: cube 3`.
 * @param[in] N    The subtree's top node.
 * @param[in] prnt The data printer, or NULL to print the structure only.
 * @param[in] strm An open stream.
 * @pre @p N is not NULL.
 * @pre @p prnt is an item printer or NULL; @p strm is an open FILE*.
 * @post A textual representation of the subtree is written to @p strm.
 * @return true if every write succeeded, false on a write error (see
 *         ferror(3)).
 */
NOCT_API bool octPrint(octNode *N, octItemPrinter *prnt, FILE *strm);

/** @} */

/* ---------------------------------------------------------------------- */
/** @name Utility operations
 * @{ */

/**
 * @brief Return the string representation of a direction.
 * @param[in] Dir A direction.
 * @pre @p Dir is a member of #octDirection.
 * @post The result is the upper-case name of @p Dir without its prefix,
 *       such as `"L"`, `"RUF"` or `"OMEGA"`.
 * @return A static string.
 */
NOCT_API const char *octDirToStr(octDirection Dir);

/**
 * @brief Return the direction named by a string.
 * @param[in] Str A direction's name, in upper or lower case (as printed by
 *                octDirToStr(), case-insensitively).
 * @pre @p Str is a valid upper- or lower-case string representation of a
 *      direction. Use octParseDir() for input that may not be.
 * @post octDirToStr(octStrToDir(Str)) equals @p Str up to case.
 * @return The direction.
 */
NOCT_API octDirection octStrToDir(const char *Str);

/**
 * @brief Parse a direction name that may be invalid, such as user input.
 *
 * The non-aborting counterpart of octStrToDir().
 * @param[in]  Str A string, or NULL.
 * @param[out] Dir Receives the direction on success.
 * @pre @p Dir is not NULL.
 * @post On success @p *Dir is the direction named by @p Str (compared
 *       case-insensitively); on failure @p *Dir is unchanged.
 * @return true if @p Str names a direction, false otherwise.
 */
NOCT_API bool octParseDir(const char *Str, octDirection *Dir);

/** @} */

#ifdef __cplusplus
}
#endif

#if NOCT_INLINE_ACCESSORS
#  include <noctree/octree_inline.h>
#endif

/** @} */
#endif /* NOCTREE_OCTREE_H */
