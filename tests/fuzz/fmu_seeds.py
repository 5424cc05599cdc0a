#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the seed programs of tests/fuzz/fuzz_fmu.c into corpus/fmu/ (run it after a
change of the harness's byte code). Each seed is a plain run an importer would make, which
the fuzzer then mutates: an instance over the cleat in step mode, steps across it, a state
taken, corrupted at a chosen byte (the mode at byte 24, a flag, a string's end), set, and
moved into a new instance."""
import os

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "fmu")
# number() table indices: 0 -> 0, 4 -> -0.3, 5 -> 7500, 3 -> 0.05, 10 -> 0.9
MODEL, ROAD = 128, 130   # reference(): 100 + b % 4
SPRINGS, CAM, CLEAT = 0, 1, 8


def run(model, corrupt_at, corrupt_to, move):
    b = [0]                                   # instantiate, proper
    b += [0, 0, 0, 0, 0, 0, 0]                # fmi2SetupExperiment(0, 0, 0, 0, 0)
    b += [7, 0, MODEL, model]                 # model
    b += [7, 0, ROAD, CLEAT]                  # road_file = cleat.csv
    b += [1, 0]                               # enter initialization
    b += [5, 0, 2, 3, 4, 5, 1]                # x = -0.3 m, load = 7500 N
    b += [2, 0]                               # exit initialization
    for x in (4, 0, 3, 10):                   # steps to x = -0.3, 0, 0.05, 0.9
        b += [5, 0, 2, 2, x, x, 0, 9, 0, 0, 0, 6, 0, 4, 5, 6]
    b += [10, 0]                              # fmi2GetFMUstate into slot 0
    b += [9, 0, 0, 0]                         # another step
    b += [13, 0, 1, corrupt_at >> 8, corrupt_at & 255, corrupt_to, 0]
    b += [11, 0]                              # fmi2SetFMUstate slot 0
    b += [9, 0, 0, 0, 6, 0, 4, 5, 6]          # step, read
    if move:
        b += [18, 0, 0, 4]                    # the state into a new instance
    b += [14, 1, 0, 40] + [0] * 40            # raw bytes as a state
    b += [15, 0, 1, 1, 2, 0]                  # fmi2SetDebugLogging(c, 1, 2, NULL)
    b += [9, 0, 1, 7, 0]                      # fmi2DoStep with an infinite step
    b += [3, 0, 4, 0]                         # terminate, reset
    return bytes(b)


seeds = {
    "springs_state_mode": run(SPRINGS, 24, 0x40, True),
    "springs_state_flag": run(SPRINGS, 40 + 64 + 2048 + 8 * 13 + 8, 7, True),
    "cam_state_intact": run(CAM, 0, ord("T"), True),
    "cam_state_string": run(CAM, 40 + 63, ord("x"), False),
}
for name, data in seeds.items():
    with open(os.path.join(HERE, name), "wb") as fp:
        fp.write(data)
