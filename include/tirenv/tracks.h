/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: the tire's width over a road that varies across it: several tracks side by side
 * under one tire, combined into one effective height and slope (docs/models.md section 13).
 * The core API: the tracks come as profiles; a road file's reader extracts them
 * (profile_file.h). */
#ifndef TIRENV_TRACKS_H
#define TIRENV_TRACKS_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/model.h"
#include "tirenv/profile.h"

TIRENV_BEGIN_DECLS

/* How a model type combines tracks, each track weighted by its share w_i of the width
 * (sum w_i = 1); docs/models.md section 13 gives the reasons. */
typedef enum {
    TIRENV_TRACKS_MEAN = 0,     /* the weighted mean of the tracks' points (z, h, slope, fx,
                                 * fz): the empirical effective-height models (cam, nn,
                                 * point), as MF-Swift averages the cams it sets across the
                                 * width */
    TIRENV_TRACKS_HIGHEST,      /* the highest track's point: a rigid disc as wide as the tire
                                 * rests on the highest ground under it (rigid) */
    TIRENV_TRACKS_EQUILIBRIUM   /* one centre height z shared by the slices, each carrying its
                                 * share of the load: sum_i w_i F_z,i(x, z) = G, the hub
                                 * forces likewise summed (springs, ring) */
} tirenv_tracks_rule;

/* The rule of a model type. */
tirenv_tracks_rule tirenv_model_type_tracks(const tirenv_model_type *type);
/* "mean", "highest", "equilibrium"; NULL for another value. */
const char *tirenv_tracks_rule_name(tirenv_tracks_rule rule);

/* Lateral positions (m) of n >= 1 tracks spread over a tire of width w >= 0 (m) centred at
 * v (m): the centres of n equal slices, v - w/2 + (i + 1/2)*w/n, into v_out[n]; a single track
 * is at v. TIRENV_EINVAL for n = 0 or a width or position that is not finite. */
int tirenv_tracks_spread(size_t n, double v, double width, double v_out[], tirenv_diag *diag);

/* Sets n >= 1 ground profiles (borrowed: they must outlive their use) side by side under the
 * tire, with weights[n] (> 0, normalised to sum 1; NULL: equal), and the load (N). The
 * evaluations that follow combine the tracks by the type's rule. A profile given more than
 * once (the same object) is one track with the weights summed, so n copies of one pointer are
 * tirenv_model_set bit for bit; profiles that are only equal in content are separate tracks,
 * which agree with one track to round-off. Resets the warm start. On failure the model is
 * unset. */
int tirenv_model_set_tracks(tirenv_model *m, size_t n, const tirenv_profile *const profiles[],
                            const double weights[], double load, tirenv_diag *diag);

/* Replaces the profiles of a model set by tirenv_model_set_tracks (n and the pattern of
 * repeated objects as then), keeping load, weights and warm start: the next window of each
 * track, for tirenv_model_stream_tracks. TIRENV_EINVAL otherwise (the model is then unset). */
int tirenv_model_set_track_profiles(tirenv_model *m, size_t n,
                                    const tirenv_profile *const profiles[], tirenv_diag *diag);

/* Distinct tracks of the last set (1 after tirenv_model_set); 0 before any. */
size_t tirenv_model_tracks(const tirenv_model *m);

TIRENV_END_DECLS
#endif
