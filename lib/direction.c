/* SPDX-License-Identifier: MIT */
/* The utility operations: directions to and from their names. */
#include "config.h"

#include <ctype.h>
#include <stddef.h>

#include "internal.h"

/* Indexed by octDirection; the report's names (Figure 1). */
static const char *const dir_names[OCT_OMEGA + 1] = {
    "L",   "R",   "D",   "U",   "B",   "F",
    "LD",  "LU",  "LB",  "LF",  "RD",  "RU",
    "RB",  "RF",  "DB",  "DF",  "UB",  "UF",
    "LDB", "LDF", "LUB", "LUF", "RDB", "RDF", "RUB", "RUF",
    "OMEGA",
};

const char *octDirToStr(octDirection Dir)
{
    NOCT_REQUIRE((unsigned)Dir <= (unsigned)OCT_OMEGA);
    if ((unsigned)Dir > (unsigned)OCT_OMEGA)
        return "?";
    return dir_names[Dir];
}

static bool equal_nocase(const char *a, const char *b)
{
    for (; *a != '\0' && *b != '\0'; ++a, ++b)
        if (toupper((unsigned char)*a) != (unsigned char)*b)
            return false;
    return *a == *b;
}

bool octParseDir(const char *Str, octDirection *Dir)
{
    NOCT_REQUIRE(Dir != NULL);
    if (Str == NULL)
        return false;
    for (int d = 0; d <= OCT_OMEGA; ++d) {
        if (equal_nocase(Str, dir_names[d])) {
            *Dir = (octDirection)d;
            return true;
        }
    }
    return false;
}

octDirection octStrToDir(const char *Str)
{
    octDirection d = OCT_OMEGA;
    bool valid = octParseDir(Str, &d);
    NOCT_REQUIRE(valid);
    (void)valid;
    return d;
}
