/* The reference for the Python module's bit-for-bit test: what 'tirenv envelope --model M
 * --tire T --cleat L,H --contact-length C' computes (the same calls, the same positions as
 * src/cli/cmd_envelope.c), printed with %a, every bit. SPDX-License-Identifier:
 * Apache-2.0
 * usage: envelope_ref MODEL TIRE L H CONTACT_LENGTH */
#include <stdio.h>
#include <stdlib.h>

#include <tirenv/tirenv.h>

static int fail(const tirenv_diag *diag)
{
    char buf[1200];
    fprintf(stderr, "envelope_ref: %s\n", tirenv_diag_format(diag, buf, sizeof buf));
    return 1;
}

int main(int argc, char *argv[])
{
    if (argc != 6) {
        fputs("usage: envelope_ref MODEL TIRE L H CONTACT_LENGTH\n", stderr);
        return 2;
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_tire tire = tirenv_tire_default();
    if (tirenv_tir_read(argv[2], &tire, &diag))
        return fail(&diag);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_type_find(argv[1]), &tire);
    tirenv_profile *p = tirenv_profile_cleat(strtod(argv[3], NULL), strtod(argv[4], NULL));
    double load, first, last;
    if (!m || !p || tirenv_model_load_for_contact_length(m, strtod(argv[5], NULL), &load, &diag))
        return fail(&diag);
    tirenv_profile_extent(p, &first, &last);
    const tirenv_positions s = tirenv_positions_default(first, last, tire.springs.R0);
    const size_t n = tirenv_positions_count(s.x_from, s.x_to, s.dx);
    double *x = malloc(n * sizeof *x);
    tirenv_point *pt = malloc(n * sizeof *pt);
    if (!x || !pt)
        return 1;
    for (size_t k = 0; k < n; ++k)
        x[k] = s.x_from + (double)k * s.dx;
    if (tirenv_model_set(m, p, load, &diag) || tirenv_model_envelope(m, n, x, pt, NULL, &diag))
        return fail(&diag);
    printf("%a\n", load);
    for (size_t k = 0; k < n; ++k)
        printf("%a %a %a %a %a %a %zu %zu\n", pt[k].x, pt[k].z, pt[k].h, pt[k].slope,
               pt[k].fx, pt[k].fz, pt[k].contacts, pt[k].iterations);
    free(pt);
    free(x);
    tirenv_profile_free(p);
    tirenv_model_free(m);
    return 0;
}
