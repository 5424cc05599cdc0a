/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the model driver: what model.c and model_state.c share. */
#ifndef TIRENV_MODEL_STATE_H
#define TIRENV_MODEL_STATE_H

#include "tirenv/tire.h"

/* A fingerprint of every parameter of a tire (FNV-1a over their bits), so that a state is
 * restored only into a model of the same tire. */
unsigned long long tirenv_model__tire_print(const tirenv_tire *tire);

#endif
