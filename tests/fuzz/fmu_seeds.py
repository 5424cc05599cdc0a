#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the seed programs of tests/fuzz/fuzz_fmu.c into corpus/fmu/ (run it after a
change of the harness's byte code). Each seed is a plain run an importer would make, which
the fuzzer then mutates: an instance over the cleat in step mode, steps across it, a state
taken, corrupted at a chosen byte (the mode at byte 24, a flag, a string's end) or a word of
8 with the model state's checksum made again (the springs model's carry), set, and moved
into a new instance."""
import os

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "fmu")
# number() table indices: 0 -> 0, 4 -> -0.3, 5 -> 7500, 3 -> 0.05, 10 -> 0.9
MODEL, TIRE, ROAD = 128, 129, 130   # reference(): 100 + b % 4
SPRINGS, CAM, EMPTY, CLEAT = 0, 1, 7, 8   # string()'s table


def run(model, corrupt_at, corrupt_to, move, word=None, xs=(4, 0, 3, 10)):
    b = [0]                                   # instantiate, proper
    b += [0, 0, 0, 0, 0, 0, 0]                # fmi2SetupExperiment(0, 0, 0, 0, 0)
    b += [7, 0, MODEL, model]                 # model
    b += [7, 0, ROAD, CLEAT]                  # road_file = cleat.csv
    b += [7, 0, TIRE, EMPTY]                  # tire_file = "": the built-in tire
    b += [1, 0]                               # enter initialization
    b += [5, 0, 2, 3, 4, 5, 1]                # x = -0.3 m, load = 7500 N
    b += [2, 0]                               # exit initialization
    for x in xs:                              # steps to x = -0.3, 0, 0.05, 0.9
        b += [5, 0, 2, 2, x, x, 0, 9, 0, 0, 0, 6, 0, 4, 5, 6]
    b += [10, 0]                              # fmi2GetFMUstate into slot 0
    b += [9, 0, 0, 0]                         # another step
    if word is None:                          # one byte changed
        b += [13, 0, 1, corrupt_at >> 8, corrupt_at & 255, corrupt_to, 0]
    else:                                     # 8 bytes, the model's checksum made again
        b += [13, 0, 1 | 4 | 8, corrupt_at >> 8, corrupt_at & 255]
        b += list(word.to_bytes(8, "little", signed=True)) + [0]
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
    # a state on the cleat (the last step at x = 0.05 m) with 8 bytes of the springs model's
    # carry changed and resealed: the rays' memos (a vertex far out, -1), the QP's base
    # (offsets into the serialized state: the FMU's 2,288 bytes, then the model's)
    "springs_carry_memo": run(SPRINGS, 2288 + 3529, 0, True, 1 << 40, (4, 0, 3)),
    "springs_carry_memo_end": run(SPRINGS, 2288 + 4237, 0, True, -1, (4, 0, 3)),
    "springs_carry_base": run(SPRINGS, 2288 + 10163, 0, True, -1, (4, 0, 3)),
    "cam_state_intact": run(CAM, 0, ord("T"), True),
    "cam_state_string": run(CAM, 40 + 63, ord("x"), False),
}
for name, data in seeds.items():
    with open(os.path.join(HERE, name), "wb") as fp:
        fp.write(data)
