/* Random road profiles of the ISO 8608 road classes. SPDX-License-Identifier: Apache-2.0
 *
 * ISO 8608 classifies a road by its one-sided displacement PSD fitted as
 *   Gd(n) = Gd(n0) * (n/n0)^-w,  n0 = 0.1 cycles/m, waviness w = 2,
 * with the classes A..H bounded by Gd(n0) = 32e-6 * 4^k m^3 and represented by the geometric
 * means of their bounds, Gd(n0) = 16e-6, 64e-6, 256e-6, ... 262144e-6 m^3: each class has 4
 * times the PSD, twice the amplitude, of the one before.
 *
 * The road is the classical sum of cosines with random phases,
 *   z(x) = sum_k A_k cos(2 pi n_k x + phi_k),  A_k = sqrt(2 Gd(n_k) dn),
 * over every spatial frequency n_k = k dn of the band [n_min, n_max] (the standard's 0.011 to
 * 2.83 cycles/m by default): each cosine carries the variance A_k^2/2 = Gd(n_k) dn of its
 * slice of the spectrum, and the phases phi_k are uniform on [0, 2 pi), drawn in order of k
 * from tirenv's xoshiro256** (tirenv/rng.h) with the given seed. The frequency resolution is the finest the road
 * allows: dn = 1/(M dx), with M the smallest power of two >= the number of vertices N, so
 * 1/(2L) < dn <= 1/L for a road of length L; the road's period M dx is at least L, so nothing
 * repeats within it. On this grid the sum is exactly an inverse real FFT of length M: the
 * cosines are evaluated at every vertex in O(M log M) (the radix-2 FFT of core/fft.c)
 * instead of O(N K) for K cosines, with no interpolation. The amplitudes are deterministic
 * and only the phases random, so the PSD holds exactly on the generation grid; estimated on
 * other grids (Welch's method) it scatters like any Gaussian road's, many cosines per bin. */
#include "tirenv/road.h"

#include <math.h>
#include <stdlib.h>
#include "core/fft.h"
#include "tirenv/rng.h"

#include "profile/profile_impl.h"

tirenv_road_settings tirenv_road_default(void)
{
    return (tirenv_road_settings){
        .road_class = 'C',
        .length = 100.0,
        .dx = 0.01,
        .seed = 1,
        .n_min = 0.011,
        .n_max = 2.83,
        .waviness = 2.0,
    };
}

/* The class index k = 0 (A) .. 7 (H), or -1. */
static int class_index(char road_class)
{
    if (road_class >= 'A' && road_class <= 'H')
        return road_class - 'A';
    if (road_class >= 'a' && road_class <= 'h')
        return road_class - 'a';
    return -1;
}

/* 16e-6 * 4^k, scaled by a power of two so that it is exact: class B's road is exactly twice
 * class A's with the same seed. */
double tirenv_iso8608_gd0(char road_class)
{
    const int k = class_index(road_class);
    return k < 0 ? NAN : ldexp(16e-6, 2 * k);
}

/* Gd(n0) times a factor that does not depend on the class, for the same exactness. */
double tirenv_road_psd(const tirenv_road_settings *s, double n)
{
    const double gd0 = tirenv_iso8608_gd0(s->road_class);
    if (isnan(gd0))
        return NAN;
    if (!(n >= s->n_min && n <= s->n_max))
        return 0.0;
    return gd0 * pow(n / TIRENV_ISO8608_N0, -s->waviness);
}

static int check(const tirenv_road_settings *s, size_t *n_out, tirenv_diag *diag)
{
    if (class_index(s->road_class) < 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "class",
                            "expected an ISO 8608 road class A to H, got '%c'", s->road_class);
    if (!(s->length > 0 && isfinite(s->length)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "length",
                            "must be a positive length in m, got %g", s->length);
    if (!(s->dx > 0 && isfinite(s->dx)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx",
                            "must be a positive length in m, got %g", s->dx);
    if (!(s->n_min > 0 && s->n_max > s->n_min && isfinite(s->n_max)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "band",
                            "expected 0 < n_min < n_max, finite, in cycles/m, got %g to %g",
                            s->n_min, s->n_max);
    if (!(s->waviness >= 0 && isfinite(s->waviness)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "waviness",
                            "must be zero or positive, got %g", s->waviness);
    if (!(s->dx * s->n_max <= 0.5))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx",
                            "%g m cannot carry %g cycles/m (the band's top) without aliasing; "
                            "expected at most 1/(2*%g) = %g m", s->dx, s->n_max, s->n_max,
                            0.5 / s->n_max);
    const double steps = floor(s->length / s->dx + 1e-9);
    if (!(steps < TIRENV_ROAD_MAX_POINTS))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx",
                            "%g m over %g m makes %.15g points, more than %d; raise dx",
                            s->dx, s->length, steps + 1, TIRENV_ROAD_MAX_POINTS);
    *n_out = (size_t)steps + 1;
    return TIRENV_OK;
}

int tirenv_road_iso8608(const tirenv_road_settings *s, tirenv_profile **out,
                        tirenv_diag *diag)
{
    *out = NULL;
    size_t n = 0;
    int status = check(s, &n, diag);
    if (status)
        return status;
    size_t M = 2;
    while (M < n)
        M *= 2;
    const double dn = 1.0 / ((double)M * s->dx);
    /* Components strictly below the Nyquist frequency M/2 * dn: that bin is real only. */
    const double k_lo = ceil(s->n_min / dn);
    const double k_hi = fmin(floor(s->n_max / dn), (double)(M / 2 - 1));
    if (k_lo > k_hi)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "length",
                            "%g m is too short for the band %g to %g cycles/m: the frequency "
                            "resolution %g cycles/m leaves no component in it", s->length,
                            s->n_min, s->n_max, dn);

    double complex *c = calloc(M, sizeof *c);
    tirenv_rng *rng = tirenv_rng_alloc(s->seed);
    struct tirenv_profile *p = tirenv_profile__new(n);
    if (!c || !rng || !p) {
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for a road of "
                              "%zu points", n);
        goto done;
    }
    /* The backward transform sums c_k e^(2 pi i j k / M) over all k, so c_k = (A_k/2)
     * e^(i phi_k) and its conjugate twin c_(M-k) add up to A_k cos(2 pi n_k x_j + phi_k):
     * the sum is real, to round-off, whose imaginary part is dropped. */
    for (size_t k = (size_t)k_lo; k <= (size_t)k_hi; k++) {
        const double A = sqrt(2.0 * tirenv_road_psd(s, (double)k * dn) * dn);
        const double phi = 2.0 * M_PI * tirenv_rng_uniform(rng);
        c[k] = 0.5 * A * cos(phi) + I * (0.5 * A * sin(phi));
        c[M - k] = conj(c[k]);
    }
    tirenv_core__fft(c, M, +1);
    for (size_t j = 0; j < n; j++) {
        p->x[j] = (double)j * s->dx;
        p->z[j] = creal(c[j]) - creal(c[0]);
        /* Only the PSD's exponent reaches overflow: (n/n0)^-w at the band's lowest
         * component passes 1e308 for w of some 300 and more. */
        if (!isfinite(p->z[j])) {
            status = tirenv_error(diag, TIRENV_EINVAL, "", 0, "waviness",
                                  "%g makes the PSD %g m^3 at %g cycles/m, the band's "
                                  "lowest component, and the heights overflow; expected a "
                                  "smaller waviness", s->waviness,
                                  tirenv_road_psd(s, k_lo * dn), k_lo * dn);
            goto done;
        }
    }
    if (!(status = tirenv_profile__finish(p, diag))) {
        *out = p;
        p = NULL;
    }
done:
    tirenv_profile_free(p);
    tirenv_rng_free(rng);
    free(c);
    return status;
}
