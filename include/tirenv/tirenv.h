/* tirenv: quasi-static enveloping models of a tractor tire over short obstacles.
 * Umbrella header. SPDX-License-Identifier: Apache-2.0
 *
 * Two layers, as Lua's lua.h and lauxlib.h. The core computes and knows no file format:
 * decls, error, parallel, rng, version, profile, xn, road, tire, model, tracks, rigid, cam,
 * springs, ring, stream, nn, nn_road, train, vehicle, ride, comfort (src/core, src/profile,
 * src/model, src/nn, src/train, src/ride include no other header; cmake/TirenvLayers.cmake
 * lists them). The auxiliary layer reads and writes files
 * and runs the study on top of the core's public headers alone: io (numtext, outfile,
 * profile_csv, tir), crg, rdf, profile_file, curve, rig, dataset, nn_file, vehicle_file,
 * sweep, study, plot (src/io, src/formats, src/rig, src/dataset, src/sweep, src/study). */
#ifndef TIRENV_TIRENV_H
#define TIRENV_TIRENV_H

#include "tirenv/error.h"
#include "tirenv/parallel.h"
#include "tirenv/profile.h"
#include "tirenv/xn.h"
#include "tirenv/road.h"
#include "tirenv/tire.h"
#include "tirenv/model.h"
#include "tirenv/tracks.h"
#include "tirenv/rigid.h"
#include "tirenv/cam.h"
#include "tirenv/springs.h"
#include "tirenv/ring.h"
#include "tirenv/io.h"
#include "tirenv/numtext.h"
#include "tirenv/outfile.h"
#include "tirenv/profile_csv.h"
#include "tirenv/tir.h"
#include "tirenv/crg.h"
#include "tirenv/rdf.h"
#include "tirenv/profile_file.h"
#include "tirenv/stream.h"
#include "tirenv/curve.h"
#include "tirenv/rig.h"
#include "tirenv/dataset.h"
#include "tirenv/nn_file.h"
#include "tirenv/plot.h"
#include "tirenv/nn_road.h"
#include "tirenv/vehicle.h"
#include "tirenv/vehicle_file.h"
#include "tirenv/ride.h"
#include "tirenv/comfort.h"
#include "tirenv/rng.h"
#include "tirenv/nn.h"
#include "tirenv/train.h"
#include "tirenv/study.h"
#include "tirenv/sweep.h"
#include "tirenv/version.h"

#endif
