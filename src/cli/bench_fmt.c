/* tirenv bench, the CSV numbers: tirenv_fmt_g against snprintf's "%.9g" on the kinds of
 * values the writers format (sweep positions, heights in m, forces in N), the same bytes
 * checked on every value. SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/bench.h"

enum { FMT_N = 1000000 };

/* Deterministic values: a 1 mm sweep from -0.7 m, heights within +-5 cm, forces up to
 * 13 kN, in turn. */
static void values(double v[])
{
    unsigned long long s = 0x9e3779b97f4a7c15ULL;
    for (size_t i = 0; i < FMT_N; ++i) {
        s ^= s >> 12;
        s ^= s << 25;
        s ^= s >> 27;
        const double u = (double)((s * 0x2545f4914f6cdd1dULL) >> 11) * 0x1p-53;
        v[i] = i % 3 == 0 ? -0.7 + 0.001 * (double)(i / 3) : i % 3 == 1 ? 0.1 * (u - 0.5)
                                                                        : 13000 * u;
    }
}

int cli_bench_fmt(long repeat)
{
    double *v = malloc(FMT_N * sizeof *v);
    if (!v)
        return cli_fail(TIRENV_ENOMEM, NULL);
    values(v);
    size_t differ = 0, sink = 0;
    for (size_t i = 0; i < FMT_N; ++i) {
        char a[TIRENV_FMT_G_SIZE], b[TIRENV_FMT_G_SIZE];
        snprintf(a, sizeof a, "%.9g", v[i]);
        tirenv_fmt_g(v[i], 9, b);
        differ += strcmp(a, b) != 0;
    }
    double best_fmt = 1e300, best_printf = 1e300;
    for (long r = 0; r < repeat; ++r) {
        char buf[TIRENV_FMT_G_SIZE];
        double t0 = cli_wall_seconds();
        for (size_t i = 0; i < FMT_N; ++i)
            sink += tirenv_fmt_g(v[i], 9, buf);
        double t1 = cli_wall_seconds();
        if (t1 - t0 < best_fmt)
            best_fmt = t1 - t0;
        t0 = cli_wall_seconds();
        for (size_t i = 0; i < FMT_N; ++i)
            sink += (size_t)snprintf(buf, sizeof buf, "%.9g", v[i]);
        t1 = cli_wall_seconds();
        if (t1 - t0 < best_printf)
            best_printf = t1 - t0;
    }
    free(v);
    const double ns_fmt = 1e9 * best_fmt / FMT_N, ns_printf = 1e9 * best_printf / FMT_N;
    cli_bench_figure("csv_fmt_ns", ns_fmt);
    cli_bench_figure("csv_snprintf_ns", ns_printf);
    cli_bench_figure("csv_fmt_speedup", best_printf / best_fmt);
    cli_bench_say("\nCSV numbers: %d values as \"%%.9g\" (sweep positions, heights, forces), "
                  "best of %ld%s\n  tirenv_fmt_g %6.1f ns a number, snprintf %6.1f ns: %.1f x "
                  "faster, %s\n", FMT_N, repeat, sink ? "" : " ", ns_fmt, ns_printf,
                  best_printf / best_fmt, differ ? "BYTES DIFFER" : "the same bytes");
    if (differ) {
        cli_error("bench: tirenv_fmt_g differs from snprintf on %zu values", differ);
        return CLI_EXIT_DATA;
    }
    return CLI_EXIT_OK;
}
