/* SPDX-License-Identifier: Apache-2.0 */
/* The README's program, line for line after this line (tests/package/install.sh checks it). */
/* envelope.c: the springs model's enveloping curve over a 0.30 x 0.10 m cleat at a 0.33 m
 * contact length, every 1 mm, in the CSV that 'tirenv envelope' writes.
 *   envelope TIRE.tir > curve.csv */
#include <stdio.h>

#include <tirenv/tirenv.h>

static int fail(const char *what, const tirenv_diag *diag)
{
    char msg[1024];
    fprintf(stderr, "envelope: %s: %s\n", what, tirenv_diag_format(diag, msg, sizeof msg));
    return 1;
}

int main(int argc, char *argv[])
{
    if (argc != 2) {
        fprintf(stderr, "usage: envelope TIRE.tir\n");
        return 1;
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_tire tire = tirenv_tire_default();   /* then the keys the file gives */
    if (tirenv_tir_read(argv[1], &tire, &diag))
        return fail(argv[1], &diag);

    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tire);
    tirenv_profile *cleat = tirenv_profile_cleat(0.30, 0.10);  /* L x H, m, centred at 0 */
    if (!m || !cleat) {
        fprintf(stderr, "envelope: out of memory, or a bad tire\n");
        return 1;
    }
    int code = 0;
    double load;  /* N */
    if (tirenv_model_load_for_contact_length(m, 0.33, &load, &diag) ||
        tirenv_model_set(m, cleat, load, &diag)) {
        code = fail("setting the model", &diag);
    } else {
        /* The sweep of 'tirenv envelope': every 1 mm from R0 + 2 cm before the cleat to
         * R0 + 2 cm after. */
        double first, last;  /* m */
        tirenv_profile_extent(cleat, &first, &last);
        const tirenv_positions s = tirenv_positions_default(first, last, tire.springs.R0);
        const size_t n = tirenv_positions_count(s.x_from, s.x_to, s.dx);
        printf("x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations\n");
        for (size_t k = 0; k < n && !code; ++k) {
            tirenv_point p;
            if (tirenv_model_eval(m, s.x_from + (double)k * s.dx, &p, &diag))
                code = fail("no equilibrium", &diag);  /* diag names x and the load */
            else  /* h: effective height (m); fx, fz: hub forces (N) */
                printf("%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%zu,%zu\n", p.x, p.z, p.h, p.slope,
                       p.fx, p.fz, p.contacts, p.iterations);
        }
    }
    tirenv_profile_free(cleat);
    tirenv_model_free(m);
    if (!code && (fflush(stdout) != 0 || ferror(stdout))) {
        perror("envelope: writing the curve");
        code = 1;
    }
    return code;
}
