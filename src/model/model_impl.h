/* Private: what a model algorithm provides to the generic driver in model.c. */
#ifndef TIRENV_MODEL_IMPL_H
#define TIRENV_MODEL_IMPL_H

#include "tirenv/model.h"

struct tirenv_model_type {
    const char *name;
    void *(*alloc)(const tirenv_tire *tire);              /* NULL on failure */
    void (*free)(void *state);
    int (*flat)(void *state, double load, tirenv_flat *out, tirenv_diag *diag);
    int (*load_for_contact_length)(void *state, double l_c, double *load, tirenv_diag *diag);
    /* New profile and load; z_flat is the model's flat-ground centre height at that load. */
    int (*set)(void *state, const tirenv_profile *p, double load, double z_flat,
               tirenv_diag *diag);
    int (*eval)(void *state, double x, tirenv_point *out, tirenv_diag *diag);
    /* Optional: swap in another window of the same ground, keeping load, z_flat and the warm
     * start (streaming); NULL falls back to set, which restarts the warm start. */
    void (*set_profile)(void *state, const tirenv_profile *p);
    /* Optional: how far from x (m) eval reads the profile at the load set; NULL means the
     * default of tirenv_model_reach, TIRENV_MODEL__REACH*R0. */
    double (*reach)(const void *state);
};

/* The default reach in units of R0: a tire of free radius R0 touches no ground farther than
 * R0 from its centre; 5 % covers a tread standing out of the free circle. */
#define TIRENV_MODEL__REACH 1.05

#endif
