/* The road's local level along a sweep for the commands that write h (--relative-to ground).
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/level.h"

int cli_parse_relative_to(void *dst, const char *arg)
{
    cli_relative_to *r = dst;
    if (strcmp(arg, "datum") == 0) {
        *r = CLI_RELATIVE_DATUM;
    } else if (strcmp(arg, "ground") == 0) {
        *r = CLI_RELATIVE_GROUND;
    } else {
        cli_error("--relative-to expects ground or datum, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

void cli_help_relative_to(FILE *fp)
{
    fputs("  --relative-to R      what h_m is measured from: datum (default), the profile's\n"
          "                       z = 0, so that h is the effective road's own height, grade\n"
          "                       and elevation included, as a vehicle model driving on it\n"
          "                       needs; or ground, the road's local level under the centre\n"
          "                       (the opening of the ground by a level segment as long as\n"
          "                       the tire's diameter, docs/models.md section 2.6), which\n"
          "                       takes grade and long undulations out and leaves what the\n"
          "                       tire makes of obstacles, as the paper's h; the same on\n"
          "                       level ground at 0. z_m stays the centre's height\n",
          fp);
}

/* Obstacles shorter than the tire's diameter are what it envelopes; longer undulations, steps
 * and grades are ground it follows (docs/models.md section 2.6). */
double cli_level_width(const tirenv_tire *tire)
{
    return 2 * tire->springs.R0;
}

struct cli_level_stream {
    tirenv_vertex_source next;
    void *ctx;
    double width;          /* m */
    double *x, *z;         /* the window's vertices, m */
    size_t n, cap;
    int bof, eof;          /* the window starts at the source's first vertex; it is read out */
    tirenv_profile *p;     /* the window as a profile, NULL until built */
};

cli_level_stream *cli_level_stream_alloc(tirenv_vertex_source source, void *ctx, double width)
{
    cli_level_stream *s = calloc(1, sizeof *s);
    if (s)
        *s = (cli_level_stream){.next = source, .ctx = ctx, .width = width, .bof = 1};
    return s;
}

void cli_level_stream_free(cli_level_stream *s)
{
    if (!s)
        return;
    free(s->x);
    free(s->z);
    tirenv_profile_free(s->p);
    free(s);
}

/* The level at x reads the ground over [x - width, x + width] and the segments reaching into
 * it: the window must hold the last vertex before x - width (or the source's first) and the
 * first after x + width (or its last). */
static int covers(const cli_level_stream *s, double x)
{
    return s->p && s->n > 0 && (s->bof || s->x[0] < x - s->width) &&
           (s->eof || s->x[s->n - 1] > x + s->width);
}

/* Drops what falls behind, reads up to 3 widths ahead, and rebuilds the profile. */
static int refill(cli_level_stream *s, double x, tirenv_diag *diag)
{
    size_t lo = 0;
    while (lo + 1 < s->n && s->x[lo + 1] < x - s->width)
        ++lo;
    if (lo > 0) {
        memmove(s->x, s->x + lo, (s->n - lo) * sizeof *s->x);
        memmove(s->z, s->z + lo, (s->n - lo) * sizeof *s->z);
        s->n -= lo;
        s->bof = 0;
    }
    while (!s->eof && !(s->n > 0 && s->x[s->n - 1] > x + 3 * s->width)) {
        double vx, vz;
        int got = 0;
        const int status = s->next(s->ctx, &vx, &vz, &got, diag);
        if (status)
            return status;
        if (!got) {
            s->eof = 1;
            break;
        }
        if (s->n == s->cap) {
            const size_t cap = s->cap ? 2 * s->cap : 256;
            double *nx = realloc(s->x, cap * sizeof *nx);
            if (nx)
                s->x = nx;
            double *nz = nx ? realloc(s->z, cap * sizeof *nz) : NULL;
            if (!nz)
                return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
            s->z = nz;
            s->cap = cap;
        }
        s->x[s->n] = vx;
        s->z[s->n++] = vz;
    }
    if (s->n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "profile", "the profile has no vertex");
    tirenv_profile_free(s->p);
    s->p = tirenv_profile_alloc(s->n, s->x, s->z);
    return s->p ? TIRENV_OK : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
}

int cli_level_stream_at(cli_level_stream *s, double x, double *level, tirenv_diag *diag)
{
    if (!covers(s, x)) {
        const int status = refill(s, x, diag);
        if (status)
            return status;
    }
    *level = tirenv_profile_level(s->p, s->width, x);
    return TIRENV_OK;
}
