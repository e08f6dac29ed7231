/* SPDX-License-Identifier: MIT */
/* A client that asks for the report's unprefixed direction names. Kept in
 * its own file so the one-letter names reach no other test code. */
#define OCT_SHORT_NAMES
#include <noctree/octree.h>

int short_names_match(void);

int short_names_match(void)
{
    static const int pairs[][2] = {
        {L, OCT_L}, {R, OCT_R}, {D, OCT_D}, {U, OCT_U}, {B, OCT_B},
        {F, OCT_F}, {LD, OCT_LD}, {LU, OCT_LU}, {LB, OCT_LB}, {LF, OCT_LF},
        {RD, OCT_RD}, {RU, OCT_RU}, {RB, OCT_RB}, {RF, OCT_RF},
        {DB, OCT_DB}, {DF, OCT_DF}, {UB, OCT_UB}, {UF, OCT_UF},
        {LDB, OCT_LDB}, {LDF, OCT_LDF}, {LUB, OCT_LUB}, {LUF, OCT_LUF},
        {RDB, OCT_RDB}, {RDF, OCT_RDF}, {RUB, OCT_RUB}, {RUF, OCT_RUF},
        {OMEGA, OCT_OMEGA}};
    for (unsigned i = 0; i < sizeof pairs / sizeof *pairs; ++i)
        if (pairs[i][0] != pairs[i][1] || pairs[i][1] != (int)i)
            return 0;
    return octStrToDir("RUF") == RUF;
}
