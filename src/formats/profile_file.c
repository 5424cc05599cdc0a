/* The rules of road-file formats, each written once: told by content when reading (the open
 * road file, road_file.c, applies them), by extension when writing; and the writers.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/profile_file.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "tirenv/numtext.h"
#include "tirenv/outfile.h"
#include "tirenv/profile_csv.h"
#include "io/io.h"

static const char *const format_names[] = {"csv", "crg", "rdf"};

const char *tirenv_profile_format_name(tirenv_profile_format f)
{
    return (unsigned)f < 3 ? format_names[f] : NULL;
}

tirenv_profile_source tirenv_profile_source_default(void)
{
    return (tirenv_profile_source){.crg = tirenv_crg_track_default(),
                                   .rdf_side = TIRENV_RDF_MEAN};
}

/* A CRG header starts with one of its section keywords (after '*' comment lines); a
 * TeimOrbit comment line may also start with '$', but not with one of these words. */
static int crg_section(const char *s, size_t n)
{
    static const char *const kw[] = {"CT", "ROAD_CRG", "ROAD_CRG_MPRO", "KD_DEFINITION",
                                     "ROAD_CRG_OPTS", "ROAD_CRG_MODS", "ROAD_CRG_FILE"};
    size_t m = 0;
    while (m < n && (isalnum((unsigned char)s[m]) || s[m] == '_'))
        m++;
    for (size_t k = 0; k < sizeof kw / sizeof kw[0]; k++)
        if (m == strlen(kw[k]) && strncasecmp(s, kw[k], m) == 0)
            return 1;
    return 0;
}

tirenv_profile_format tirenv_profile_detect_memory(const void *data, size_t size)
{
    const char *p = data, *end = p + size;
    if (size >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0)
        p += 3;
    while (p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        const char *eol = nl ? nl : end;
        const char *s = p;
        while (s < eol && (*s == ' ' || *s == '\t' || *s == '\r'))
            s++;
        if (s < eol) {
            if (*s == '*')
                return TIRENV_PROFILE_CRG;
            if (*s == '$' && crg_section(s + 1, (size_t)(eol - s - 1)))
                return TIRENV_PROFILE_CRG;
            if (*s == '[')
                return TIRENV_PROFILE_RDF;
            if (*s != '$' && *s != '!')
                return TIRENV_PROFILE_CSV;
        }
        p = nl ? nl + 1 : end;
    }
    return TIRENV_PROFILE_CSV;
}

int tirenv_profile_format_of_name(const char *path, tirenv_profile_format *f)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    for (int k = 0; dot && k < 3; k++)
        if (strcasecmp(dot + 1, format_names[k]) == 0) {
            *f = (tirenv_profile_format)k;
            return TIRENV_OK;
        }
    return TIRENV_EINVAL;
}

int tirenv_profile_write_csv(const char *path, const tirenv_profile *p, const char *comment,
                             tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    tirenv_outfile *f;
    const int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fputs("x_m,z_m\n", fp);
    tirenv_outfile_comment(f, comment);
    const size_t n = tirenv_profile_size(p);
    const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
    char a[TIRENV_FMT_G_SIZE], b[TIRENV_FMT_G_SIZE];
    for (size_t k = 0; k < n; k++) {
        tirenv_fmt_shortest(x[k], a);
        tirenv_fmt_shortest(z[k], b);
        fprintf(fp, "%s,%s\n", a, b);
    }
    return tirenv_outfile_commit(f, diag);
}

tirenv_profile_write_options tirenv_profile_write_default(void)
{
    return (tirenv_profile_write_options){.crg_encoding = TIRENV_CRG_KDBI,
                                          .crg_u_increment = 0,
                                          .crg_half_width = 0.5,
                                          .comment = NULL};
}

int tirenv_profile_write_file(const char *path, const tirenv_profile *p,
                              const tirenv_profile_write_options *o, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    const tirenv_profile_write_options def = tirenv_profile_write_default();
    if (!o)
        o = &def;
    tirenv_profile_format f;
    if (tirenv_profile_format_of_name(path, &f) != TIRENV_OK &&
        tirenv_outfile_path_is_through(path))
        f = TIRENV_PROFILE_CSV; /* "-", /dev/null, a FIFO without an extension: CSV */
    else if (tirenv_profile_format_of_name(path, &f) != TIRENV_OK)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "", "unknown extension; expected a "
                            "file name ending in .csv, .crg or .rdf");
    switch (f) {
    case TIRENV_PROFILE_CSV:
        return tirenv_profile_write_csv(path, p, o->comment, diag);
    case TIRENV_PROFILE_RDF:
        return tirenv_rdf_write(path, p, NULL, o->comment, diag);
    case TIRENV_PROFILE_CRG: {
        if (!(o->crg_half_width > 0))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "crg_half_width",
                                "half width %g; expected a positive length, m",
                                o->crg_half_width);
        const double v[2] = {-o->crg_half_width, o->crg_half_width};
        const tirenv_profile *const tracks[2] = {p, p};
        return tirenv_crg_write_profiles(path, o->crg_encoding, 2, v, tracks,
                                         o->crg_u_increment, o->comment, diag);
    }
    }
    return tirenv_error(diag, TIRENV_EINVAL, path, 0, "", "unknown format");
}
