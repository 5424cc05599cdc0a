/* tirenv: quasi-static enveloping models of a tractor tire over short obstacles.
 * Umbrella header. SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TIRENV_TIRENV_H
#define TIRENV_TIRENV_H

#include "tirenv/error.h"
#include "tirenv/parallel.h"
#include "tirenv/profile.h"
#include "tirenv/road.h"
#include "tirenv/tire.h"
#include "tirenv/model.h"
#include "tirenv/rigid.h"
#include "tirenv/cam.h"
#include "tirenv/springs.h"
#include "tirenv/ring.h"
#include "tirenv/io.h"
#include "tirenv/stream.h"
#include "tirenv/curve.h"
#include "tirenv/rig.h"
#include "tirenv/dataset.h"
#include "tirenv/nn_road.h"
#include "tirenv/vehicle.h"
#include "tirenv/ride.h"
#include "tirenv/comfort.h"
#include "tirenv/nn.h"
#include "tirenv/train.h"
#include "tirenv/study.h"
#include "tirenv/sweep.h"
#include "tirenv/version.h"

#endif
