/* libFuzzer harness: the streaming road reader (tirenv_profile_file_reader_*) over a CSV
 * file, to the end of the input or its first error; CRG and RDF content is detected and read
 * by the same reader. Then the road's ends (tirenv_road_file_extent): where every row reads,
 * the ends found without the rows (a CSV's from the file's end, an OpenCRG road's from its
 * pass at open, an RDF road's from its scan) must be the same bits as those of every row
 * read.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdlib.h>
#include <string.h>

#include "fuzz_input.h"
#include "tirenv/profile_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_input_file(data, size, ".csv");
    tirenv_profile_file_reader *r = NULL;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_profile_file_reader_open(path, NULL, 1, NULL, &r, &diag) == TIRENV_OK) {
        int got = 1;
        double x, z;
        while (got && tirenv_profile_file_reader_next(r, &x, &z, &got, &diag) == TIRENV_OK)
            ;
    }
    tirenv_profile_file_reader_free(r);
    tirenv_road_file *f = NULL;
    if (tirenv_road_file_open(path, &f, &diag) == TIRENV_OK) {
        double ends[2][2];
        const int all = tirenv_road_file_extent(f, NULL, 1, NULL, 1, &ends[0][0], &ends[0][1],
                                                &diag);
        const int fast = tirenv_road_file_extent(f, NULL, 1, NULL, 0, &ends[1][0], &ends[1][1],
                                                 &diag);
        if (all == TIRENV_OK && (fast != TIRENV_OK || memcmp(ends[0], ends[1], sizeof ends[0])))
            abort();
    }
    tirenv_road_file_free(f);
    return 0;
}
