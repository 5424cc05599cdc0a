/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: the radial + interradial springs model, element level (docs/models.md section 4).
 * Most users want tirenv/model.h; this header exposes the parts for tests, plots of the
 * deformed tire, and models built on top. */
#ifndef TIRENV_SPRINGS_H
#define TIRENV_SPRINGS_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/profile.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

/* Workspace of the springs model for one tire: element angles, stiffnesses, and the state of
 * the last force evaluation. Evaluation never allocates. */
typedef struct tirenv_springs tirenv_springs;

/* NULL if the parameters are unphysical or memory runs out. */
tirenv_springs *tirenv_springs_alloc(const tirenv_springs_params *params);
void tirenv_springs_free(tirenv_springs *s);  /* NULL is a no-op */

/* The parameters the workspace was built with. */
const tirenv_springs_params *tirenv_springs_params_of(const tirenv_springs *s);

/* Number of radial elements N and their angles theta_i = i*dphi (rad, from the downward
 * vertical, positive forward), ascending. */
size_t tirenv_springs_size(const tirenv_springs *s);
const double *tirenv_springs_theta(const tirenv_springs *s);

/* Hub forces (N) with the centre at (x, z) (m) over a profile (the elements' centre: with a
 * sidewall, SIDEWALL_STIFFNESS, tirenv/model.h puts the hub below it, docs/models.md section
 * 4.9; here it is left out): casts the rays, solves the tip
 * contact exactly (with CONTACT 'continuous', the default, the QP of a tread between the
 * elements that meets every ground vertex; with 'rays' the paper's LCP along the rays), sums
 * eq. 1. dfz_dz (N/m, may be NULL) is the exact derivative of F_z on the current piece (active
 * set and hit segments fixed). TIRENV_ENOCONV, with diag (may be NULL) saying so, if the tip
 * contact does not settle; with 'rays', TIRENV_ERANGE if the ground has a feature narrower
 * than the ray spacing at its distance that reaches into the tread between two rays unseen (a
 * needle between the elements: a real tread would rest on it; the rays cannot see it), diag
 * (and tirenv_springs_refusal) saying where and how wide. */
int tirenv_springs_forces(tirenv_springs *s, const tirenv_profile *p, double x, double z,
                          double *fx, double *fz, double *dfz_dz, size_t *contacts,
                          tirenv_diag *diag);

/* Why the last tirenv_springs_forces call returned TIRENV_ERANGE: the position, the feature's
 * width, its distance from the centre and the ray spacing there; cleared if it did not. */
void tirenv_springs_refusal(const tirenv_springs *s, tirenv_diag *diag);

/* Full-length tip state of the last tirenv_springs_forces call, into caller arrays of
 * tirenv_springs_size() entries (any may be NULL): penetration d_i (m), tip deflection w_i (m),
 * contact reaction p_i (N). */
void tirenv_springs_tips(const tirenv_springs *s, double d[], double w[], double p[]);

/* The stiffnesses c_r and c_b of par (the rest as given, no sidewall: k_s and F_s0 set to
 * 0) identified on a reference model's flat ground at n loads (2 to 64): load[i] (N), its
 * deflection[i] (m) and contact_length[i] (m). The springs model then deflects as the
 * reference does and touches as much ground (least squares in log load at the reference's
 * deflections and in log contact length there, docs/models.md section 14.1). TIRENV_EINVAL for targets that are no flat-ground states;
 * the model's errors otherwise. */
int tirenv_springs_identify(tirenv_springs_params *par, size_t n, const double load[],
                            const double deflection[], const double contact_length[],
                            tirenv_diag *diag);

/* The same with the sidewall in series (docs/models.md sections 4.9 and 14.1): c_r, c_b,
 * SIDEWALL_STIFFNESS k_s and SIDEWALL_PRELOAD F_s0 of par (the rest as given) identified on n
 * loads (3 to 64, load and deflection ascending) minimising the sum of the 8th powers of the
 * log deflection's and log contact length's residuals at the reference's loads (near the
 * largest of them): golden sections nested over c_b/c_r in
 * [1e-4, 1] rad^2, c_r, F_s0 in [0, the largest load] and 1/k_s, on tables of the elements'
 * flat ground. TIRENV_EINVAL for bad targets; the model's errors otherwise. Targets that
 * want no sidewall get a stiff one (k_s far above the elements' stiffness). */
int tirenv_springs_identify_sidewall(tirenv_springs_params *par, size_t n, const double load[],
                                     const double deflection[],
                                     const double contact_length[], tirenv_diag *diag);

/* The same on m references together (1 to 4; a tire's ring and cam, docs/models.md section
 * 14.1), min-max: c_r, c_b and, where par has a sidewall (k_s > 0; else none, k_s and F_s0
 * set to 0), k_s and F_s0 that make the largest relative difference |x/x_ref - 1| of the
 * deflection and of the contact length from every reference at every load the least (the
 * sidewall, which the largest need not fix, the one with the least L^16 norm of the
 * deflection's). deflection[] and contact_length[] (m) hold m*n values, reference j's at
 * [j*n, j*n + n); the n loads (2, with a sidewall 3, to 64; N) and each reference's
 * deflections ascending.
 * TIRENV_EINVAL for bad targets; the model's errors otherwise. */
int tirenv_springs_identify_minmax(tirenv_springs_params *par, size_t n, const double load[],
                                   size_t m, const double deflection[],
                                   const double contact_length[], tirenv_diag *diag);

/* The tip LCP on its own: K w = p, w >= d, p >= 0, p.(w - d) = 0, with K the tridiagonal
 * stiffness of n elements (k_r N/m on the diagonal, k_ir N/m between neighbours, ends free).
 * work holds 4*n doubles. Returns TIRENV_ENOCONV if the active set does not settle in
 * max_iter passes; *passes (may be NULL) counts them. */
int tirenv_springs_lcp(size_t n, double k_r, double k_ir, const double d[], double w[],
                       double p[], double work[], size_t max_iter, size_t *passes);

TIRENV_END_DECLS
#endif
