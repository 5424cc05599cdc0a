/* Roads from files for the commands that take --profile, each opened once (tirenv_road_file):
 * which track of a road that varies across (--track, an OpenCRG file's lateral position), which
 * side of an RDF road (--side), and the tracks spread across the tire's width (--width,
 * --tracks; docs/models.md section 13), read whole or a row at a time.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

void cli_help_road(FILE *fp, int with_tracks)
{
    fputs("  --track V            with --profile ROAD.crg: the track at lateral position V, m,\n"
          "                       positive to the left of the reference line (default 0, the\n"
          "                       reference line); a CSV or RDF road is 2-D, the same on\n"
          "                       every track\n"
          "  --side S             with --profile ROAD.rdf: left, right or mean (default) of\n"
          "                       a poly_line road's z_left and z_right\n"
          "  --crg-nan-mode M     with --profile ROAD.crg: a missing grid value the track\n"
          "                       needs is an error (keep), the nearest valid value of its\n"
          "                       cross section (nearest, OpenCRG's default), the height M in\n"
          "                       m (a number), or as the file's GRID_NAN_MODE says (file,\n"
          "                       the default; OpenCRG's default nearest in a file without\n"
          "                       $ROAD_CRG_MODS, an error in one that does not set it)\n",
          fp);
    if (with_tracks)
        fputs("  --tracks N           evaluate N tracks across the tire's width around --track\n"
              "                       (slice centres) and combine them: springs and ring by\n"
              "                       one equilibrium of the slices, rigid by the highest, the\n"
              "                       others by the mean (docs/models.md section 13); a 2-D\n"
              "                       road is one track (default 1)\n"
              "  --width W            the width the tracks spread over, m (default: the tire\n"
              "                       file's [DIMENSION] WIDTH, 0.38 for the default tire)\n",
              fp);
}

/* A road file's options with a generated obstacle would change nothing: refused. */
static int file_options_unused(const cli_options *o)
{
    if (o->obstacle == CLI_PROFILE || !(o->have_track || o->have_side || o->have_crg_nan))
        return CLI_EXIT_OK;
    cli_error("--%s applies to a road file (--profile FILE), not to a generated obstacle",
              o->have_track ? "track" : o->have_side ? "side" : "crg-nan-mode");
    return CLI_EXIT_USAGE;
}

int cli_road_plan(const cli_options *o, const tirenv_tire *tire, cli_road *r)
{
    memset(r, 0, sizeof *r);
    r->src = tirenv_profile_source_default();
    r->format = TIRENV_PROFILE_CSV;
    r->n = 1;
    r->from_file = o->obstacle == CLI_PROFILE;
    const int unused = file_options_unused(o);
    if (unused)
        return unused;
    if (o->have_width && !o->tracks) {
        cli_error("--width W spreads the tracks of --tracks N: give --tracks too");
        return CLI_EXIT_USAGE;
    }
    if (r->from_file) {  /* opened once, its format told once: every read takes r->file */
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        const int status = tirenv_road_file_open(o->obstacle_arg, &r->file, &diag);
        if (status)
            return cli_fail(status, &diag);
        r->format = tirenv_road_file_format(r->file);
    }
    if (o->have_track && r->format != TIRENV_PROFILE_CRG) {
        cli_error("--track applies to an OpenCRG road; %s is %s, the same on every track",
                  o->obstacle_arg,
                  r->format == TIRENV_PROFILE_RDF ? "an RDF road (use --side)"
                                                  : "a CSV profile");
        return CLI_EXIT_USAGE;
    }
    if (o->have_side && r->format != TIRENV_PROFILE_RDF) {
        cli_error("--side applies to an RDF road; %s is %s", o->obstacle_arg,
                  r->format == TIRENV_PROFILE_CRG ? "an OpenCRG road (use --track)"
                                                  : "a CSV profile");
        return CLI_EXIT_USAGE;
    }
    if (o->have_crg_nan && r->format != TIRENV_PROFILE_CRG) {
        cli_error("--crg-nan-mode applies to an OpenCRG road; %s is %s", o->obstacle_arg,
                  r->format == TIRENV_PROFILE_RDF ? "an RDF road" : "a CSV profile");
        return CLI_EXIT_USAGE;
    }
    if (o->have_crg_nan) {
        r->src.crg.grid_nan_mode = o->crg_nan.grid_nan_mode;
        r->src.crg.grid_nan_offset = o->crg_nan.grid_nan_offset;
    }
    if (o->have_track)
        r->src.crg.v = o->track;
    if (o->have_side)
        r->src.rdf_side = o->side;
    r->v[0] = r->src.crg.v;
    /* A 2-D road, or a generated obstacle, is the same on every track: one track is all of
     * them, bit for bit (docs/models.md section 13.1). */
    if (o->tracks > 1 && r->format == TIRENV_PROFILE_CRG) {
        r->n = (size_t)o->tracks;
        r->width = o->have_width ? o->width : tire ? tire->width : 0;
        if (!(r->width > 0)) {
            cli_error("--tracks %ld: the tire file gives no [DIMENSION] WIDTH to spread them "
                      "over; give --width W", o->tracks);
            return CLI_EXIT_USAGE;
        }
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        const int status = tirenv_tracks_spread(r->n, r->src.crg.v, r->width, r->v, &diag);
        if (status)
            return cli_fail(status, &diag);
    }
    return CLI_EXIT_OK;
}

int cli_road_read(const cli_options *o, const cli_road *r, tirenv_profile *out[])
{
    for (size_t k = 1; k < r->n; ++k)
        out[k] = NULL;
    if (!r->from_file)
        return cli_obstacle(o, &out[0]);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_road_file_read(r->file, &r->src, r->n, r->v, out, &diag);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

int cli_road_open(const cli_road *r, tirenv_profile_file_reader **out)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_road_file_reader(r->file, &r->src, r->n, r->v, out, &diag);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

void cli_road_free(cli_road *r)
{
    tirenv_road_file_free(r->file);
    r->file = NULL;
}

int cli_profile(const cli_options *o, tirenv_profile **out)
{
    *out = NULL;
    if (o->obstacle != CLI_PROFILE) {  /* ride and rig: --track was taken and ignored */
        const int unused = file_options_unused(o);
        return unused ? unused : cli_obstacle(o, out);
    }
    cli_road r;
    int code = cli_road_plan(o, NULL, &r);
    if (!code)
        code = cli_road_read(o, &r, out);
    cli_road_free(&r);
    return code;
}

void cli_road_label(const cli_options *o, const cli_road *r, char *buf, size_t n)
{
    char name[512], v[TIRENV_FMT_G_SIZE], w[TIRENV_FMT_G_SIZE];
    cli_obstacle_label(o, name, sizeof name);
    tirenv_fmt_shortest(r->src.crg.v, v);  /* the lateral position as it reads back */
    tirenv_fmt_shortest(r->width, w);
    if (r->format == TIRENV_PROFILE_CRG && r->n > 1)
        snprintf(buf, n, "%s, %zu tracks over %s m around v = %s m", name, r->n, w, v);
    else if (r->format == TIRENV_PROFILE_CRG)
        snprintf(buf, n, "%s, track v = %s m", name, v);
    else if (r->format == TIRENV_PROFILE_RDF)
        snprintf(buf, n, "%s, side %s", name, tirenv_rdf_side_name(r->src.rdf_side));
    else
        snprintf(buf, n, "%s", name);
}
