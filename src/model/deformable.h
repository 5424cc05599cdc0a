/* SPDX-License-Identifier: Apache-2.0 */
/* Private: a deformable model is a hub-force function F(x, z) plus its own definition of the
 * flat-ground contact length; the constant-load equilibrium around it is shared
 * (deformable.c). */
#ifndef TIRENV_DEFORMABLE_H
#define TIRENV_DEFORMABLE_H

#include "core/equilibrium.h"
#include "model/model_impl.h"

typedef struct {
    const char *name;  /* the model type's, for messages */
    void *(*alloc)(const tirenv_tire *tire);
    void (*free)(void *elem);
    /* Hub forces with the centre at (x, z) (m): F_z (N), dF_z/dz (N/m), F_x (N) and the
     * contacts, all of one evaluation, in *out; a failure says what failed in diag. */
    int (*forces)(void *elem, const tirenv_profile *p, double x, double z,
                  tirenv_eq_point *out, tirenv_diag *diag);
    /* Flat-ground contact length (m) with the centre at height z (m). */
    int (*contact_length)(void *elem, const tirenv_profile *flat, double z, double *l_c,
                          tirenv_diag *diag);
    /* Flat-ground centre height z (m) at which the contact length is l_c (m), searched in
     * [z_lo, R0]: z_lo is the lowest height of the valid range (lowest_z), where the contact
     * length is the longest. */
    int (*z_for_contact_length)(void *elem, const tirenv_profile *flat, double l_c, double z_lo,
                                double *z, tirenv_diag *diag);
    /* Optional: the lowest flat-ground centre height z (m) of the model's valid range and why
     * the range ends there (a phrase for messages, into why[n]); z = 0 and "" when it ends
     * only where the centre meets the ground. NULL means that. docs/models.md section 1.3. */
    int (*lowest_z)(void *elem, const tirenv_profile *flat, double *z, char *why, size_t n,
                    tirenv_diag *diag);
    /* Optional: the bracket of the equilibrium at x (m): z_lo the ground height under the
     * centre, z_hi a height from which up nothing of the tire touches the ground, as cheaply
     * as the model knows them (the springs model has both from the rays' origin). NULL: the
     * ground height and the rigid disc's height at x, the tightest z_hi for any tire within
     * its free circle. */
    void (*bracket)(void *elem, const tirenv_profile *p, double x, double *z_lo,
                    double *z_hi);
    /* Whether the tire looks the same at every x (no lugs turning with it), so that on level
     * ground the equilibrium is the flat one; NULL means always. */
    int (*shift_invariant)(const tirenv_tire *tire);
    /* The contact state a workspace starts its next solve from, as bytes (a fixed number for
     * a tire): saved, and restored into a workspace of the same tire. */
    size_t (*state_size)(const void *elem);
    void (*state_save)(const void *elem, unsigned char *buf);
    void (*state_restore)(void *elem, const unsigned char *buf);
} tirenv_deformable_ops;

/* The model-type functions of model_impl.h for any deformable model; alloc takes the ops. */
void *tirenv_deformable_alloc(const tirenv_tire *tire, const tirenv_deformable_ops *ops);
void tirenv_deformable_free(void *state);
int tirenv_deformable_flat(void *state, double load, tirenv_flat *out, tirenv_diag *diag);
int tirenv_deformable_load_for_contact_length(void *state, double l_c, double *load,
                                              tirenv_diag *diag);
int tirenv_deformable_set(void *state, const tirenv_profile *p, double load, double z_flat,
                          tirenv_diag *diag);
int tirenv_deformable_eval(void *state, double x, tirenv_point *out, tirenv_diag *diag);
void tirenv_deformable_set_profile(void *state, const tirenv_profile *p);
/* The hub forces at (x, z) on the profile set, for the equilibrium over several tracks. */
int tirenv_deformable_forces(void *state, double x, double z, tirenv_eq_point *out,
                             tirenv_diag *diag);
int tirenv_deformable_set_load(void *state, double load, double *z_flat, tirenv_diag *diag);
size_t tirenv_deformable_state_size(const void *state);
void tirenv_deformable_state_save(const void *state, unsigned char *buf);
int tirenv_deformable_state_restore(void *state, const unsigned char *buf, tirenv_diag *diag);

#endif
