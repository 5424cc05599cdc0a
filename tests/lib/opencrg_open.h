/* SPDX-License-Identifier: Apache-2.0 */
/* OpenCRG's own sequence to open a data set, for the test programs that use the ASAM OpenCRG
 * C API as an independent reader (tests/formats/crg_opencrg*.c): load, check, apply the data
 * set's modifiers (the file's $ROAD_CRG_MODS, or OpenCRG's defaults if it states none), then
 * a contact point to evaluate it with. One program, one translation unit. */
#ifndef TIRENV_TEST_OPENCRG_OPEN_H
#define TIRENV_TEST_OPENCRG_OPEN_H

#include "crgBaseLib.h"

/* The contact point of path opened in OpenCRG's sequence, or -1 if OpenCRG does not load or
 * check it. The data set's id goes into *data_set (if not NULL; > 0 once loaded, for
 * crgDataSetRelease and the crgDataSetGet* calls). */
static int opencrg_open(const char *path, int *data_set)
{
    const int id = crgLoaderReadFile(path);
    if (data_set)
        *data_set = id;
    if (id <= 0 || !crgCheck(id))
        return -1;
    crgDataSetModifiersApply(id);
    return crgContactPointCreate(id);
}

#endif
