/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: file formats (the convenience layer): .tir tire property files, profile CSV,
 * and all-or-nothing output files. Each in its own header now (tir.h, profile_csv.h,
 * outfile.h, numtext.h); this one includes them all, for the code that includes it. */
#ifndef TIRENV_IO_H
#define TIRENV_IO_H

#include "tirenv/numtext.h"
#include "tirenv/outfile.h"
#include "tirenv/profile_csv.h"
#include "tirenv/tir.h"

#endif
