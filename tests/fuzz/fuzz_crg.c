/* libFuzzer entry point for the OpenCRG reader: any bytes as a .crg file (header parser, the
 * four encodings' row scan, header-against-data checks), then everything a caller can ask of
 * a file that opened (tracks at several v and border modes, windows, the block reader, the
 * whole grid, the reference line) and the format detector. Seeds: corpus/crg.
 * Build by hand: clang -g -O1 -fsanitize=fuzzer,address,undefined -Iinclude -Isrc
 *   tests/fuzz/fuzz_crg.c <the library's sources> -lcminpack -ljansson -lm
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdint.h>
#include <stdlib.h>

#include "tirenv/crg.h"
#include "tirenv/profile_file.h"

/* Rows asked for at once, so that a huge file does not make one allocation the size of
 * the input. */
enum { WINDOW = 64 };

static void exercise(const tirenv_crg *c)
{
    const size_t nu = tirenv_crg_rows(c), nv = tirenv_crg_long_sections(c);
    const double v0 = tirenv_crg_v(c, 0), v1 = tirenv_crg_v(c, nv - 1);
    const double vs[] = {0, v0, v1, 0.5 * (v0 + v1), v1 + 0.37, v0 - 2.9};
    double u[WINDOW], z[WINDOW];
    for (size_t k = 0; k < sizeof vs / sizeof vs[0]; k++)
        for (int mode = -1; mode <= 4; mode++) {
            tirenv_crg_track_spec s = tirenv_crg_track_default();
            s.v = vs[k];
            s.border_mode_v = mode;
            s.grid_nan_mode = mode < 0 ? -1 : mode % 3;
            const size_t n = nu < WINDOW ? nu : WINDOW;
            tirenv_crg_track_rows(c, &s, nu - n, n, u, z, NULL);
            tirenv_crg_track_rows(c, &s, 0, n, u, z, NULL);
        }
    tirenv_crg_track_spec s = tirenv_crg_track_default();
    s.v = 0.5 * (v0 + v1);
    s.grid_nan_mode = 2;
    tirenv_crg_track_reader *r;
    if (tirenv_crg_track_reader_open(c, &s, &r, NULL) == TIRENV_OK) {
        double ur, zr;
        int got = 1;
        for (size_t i = 0; got && i < 4 * WINDOW; i++)
            if (tirenv_crg_track_reader_next(r, &ur, &zr, &got, NULL))
                break;
        tirenv_crg_track_reader_free(r);
    }
    if (nu <= 4096) {
        tirenv_profile *p = NULL;
        if (tirenv_crg_track(c, &s, &p, NULL) == TIRENV_OK)
            tirenv_profile_free(p);
        double *x = malloc(nu * sizeof *x), *y = malloc(nu * sizeof *y);
        double *phi = malloc(nu * sizeof *phi);
        if (x && y && phi)
            tirenv_crg_refline(c, x, y, phi, NULL);
        free(x);
        free(y);
        free(phi);
    }
    if (nv <= 256) {
        double *g = malloc(WINDOW * nv * sizeof *g);
        if (g)
            tirenv_crg_grid_rows(c, 0, nu < WINDOW ? nu : WINDOW, g, NULL);
        free(g);
    }
    tirenv_crg_row_at(c, 1e300);
    tirenv_crg_row_at(c, -1e300);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    tirenv_profile_detect_memory(data, size);
    tirenv_crg *c = NULL;
    tirenv_diag d;
    if (tirenv_crg_open_memory(data, size, "fuzz.crg", &c, &d) == TIRENV_OK) {
        exercise(c);
        tirenv_crg_free(c);
    }
    return 0;
}
