# SPDX-License-Identifier: Apache-2.0
# The two layers of the library, in one place: the build globs its sources from these
# directories and the 'layers' test (cmake/CheckLayers.cmake) checks the boundary by them.
#
# CORE: profiles, models, equilibrium, network evaluation, trainers, ride and comfort. It knows
#   no file format, rig, data set, study or plot: it includes no AUX header, calls no AUX
#   function and does not use jansson.
# AUX (the convenience layer): file formats (.tir, .veh, CSV, JSON), rig simulation and import,
#   data sets, study, compare, plots. It is written against the core's public headers alone.
#   Its modules are listed from the bottom up, and each uses only those before it (checked by
#   the includes and by the symbols), through their public headers or their interface header
#   (below):
#     io       bytes in and out: CSV lines, number text, sources, atomic output files and
#              directories, temporary files;
#     formats  the file formats: property files and units, .tir, .veh, CSV profiles and
#              streams, OpenCRG, RDF, network JSON, curves;
#     rig      the virtual rig and the import of rig logs;
#     dataset  data sets: reading, building the embedded ones;
#     sweep    sweeps over a grid of cases, their shards and merge;
#     study    fit, compare, findings, report and plots.
# The CLI (src/cli) uses public headers of both layers and its own cli/ headers only.

# Directories under src/, one module each.
set(TIRENV_CORE_DIRS core profile model nn train ride)
set(TIRENV_AUX_DIRS io formats rig dataset sweep study)

# A module's interface to the auxiliary modules after it, if it has one, is the header named
# after the module, src/<module>/<module>.h (as SQLite's btree.h beside btreeInt.h): io's
# byte-level readers, src/io/io.h, which formats, rig and dataset read their files with, and
# src/dataset/dataset.h, the rows of a sweep's shard that sweep writes and dataset checks. Its
# other headers are its own. Not the user's interface: internal tirenv_<object>__ names.

# Every public header under include/tirenv/ belongs to exactly one layer; the check fails on a
# header listed in neither, so a new header must be placed here. (tirenv.h, the umbrella, and
# decls.h, the declaration macros, belong to both.)
set(TIRENV_CORE_HEADERS
  error.h profile.h road.h tire.h model.h tracks.h rigid.h cam.h springs.h ring.h stream.h xn.h
  nn.h nn_road.h train.h vehicle.h ride.h comfort.h version.h parallel.h rng.h)
set(TIRENV_AUX_HEADERS
  io.h numtext.h outfile.h profile_csv.h tir.h curve.h rig.h dataset.h study.h plot.h nn_file.h
  vehicle_file.h crg.h rdf.h profile_file.h sweep.h)
set(TIRENV_SHARED_HEADERS tirenv.h decls.h)

# System headers of file-format libraries: the core includes none of them.
set(TIRENV_AUX_SYSTEM_HEADERS jansson.h cminpack.h)
