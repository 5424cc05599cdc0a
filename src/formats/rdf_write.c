/* Writing TNO / Adams 2-D road files: a 'poly_line' road in SI units (or 'flat' for a profile
 * of one vertex), all or nothing. SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/numtext.h"
#include "tirenv/outfile.h"
#include "tirenv/rdf.h"
#include "tirenv/tirenv.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/io.h"

static void comment_lines(FILE *fp, const char *comment)
{
    for (const char *c = comment; c && *c;) {
        const size_t n = strcspn(c, "\n");
        fprintf(fp, "$ %.*s\n", (int)n, c);
        c += n + (c[n] == '\n');
    }
}

int tirenv_rdf_write(const char *path, const tirenv_profile *left, const tirenv_profile *right,
                     const char *comment, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (!left)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "", "no profile to write");
    if (!right)
        right = left;
    const size_t n = tirenv_profile_size(left);
    const double *x = tirenv_profile_x(left);
    if (tirenv_profile_size(right) != n || memcmp(tirenv_profile_x(right), x, n * sizeof *x))
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "", "the left and right tracks do "
                            "not share their x (%zu and %zu vertices); a poly_line row holds "
                            "both heights at one x", n, tirenv_profile_size(right));
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fprintf(fp, "$--------------------------------------------------------------MDI_HEADER\n"
                "[MDI_HEADER]\n"
                "FILE_TYPE     = 'rdf'\n"
                "FILE_VERSION  = 5.00\n"
                "FILE_FORMAT   = 'ASCII'\n"
                "$ Road profile written by tirenv %s\n", TIRENV_VERSION);
    comment_lines(fp, comment);
    fputs("$-------------------------------------------------------------------UNITS\n"
          "[UNITS]\n"
          "LENGTH        = 'meter'\n"
          "FORCE         = 'newton'\n"
          "ANGLE         = 'radians'\n"
          "MASS          = 'kg'\n"
          "TIME          = 'sec'\n"
          "$-------------------------------------------------------------------MODEL\n"
          "[MODEL]\n"
          "METHOD        = '2D'\n", fp);
    const double *zl = tirenv_profile_z(left), *zr = tirenv_profile_z(right);
    char a[TIRENV_FMT_G_SIZE], b[TIRENV_FMT_G_SIZE], c[TIRENV_FMT_G_SIZE];
    if (n == 1 && zl[0] == zr[0]) {
        tirenv_fmt_shortest(zl[0], a);
        fprintf(fp, "ROAD_TYPE     = 'flat'\n"
                    "$--------------------------------------------------------------PARAMETERS\n"
                    "[PARAMETERS]\n"
                    "OFFSET        = %s $ height of the flat road, m\n"
                    "MU            = 1.0\n", a);
    } else {
        fputs("ROAD_TYPE     = 'poly_line'\n"
              "$--------------------------------------------------------------PARAMETERS\n"
              "[PARAMETERS]\n"
              "OFFSET                  = 0\n"
              "ROTATION_ANGLE_XY_PLANE = 0\n"
              "MU                      = 1.0\n"
              "$ x_road z_left z_right, m\n"
              "(XZ_DATA)\n", fp);
        for (size_t k = 0; k < n; k++) {
            tirenv_fmt_shortest(x[k], a);
            tirenv_fmt_shortest(zl[k], b);
            tirenv_fmt_shortest(zr[k], c);
            fprintf(fp, "%s %s %s\n", a, b, c);
        }
    }
    return tirenv_outfile_commit(f, diag);
}
