/* Writes the FMU's modelDescription.xml to the file named by its argument (build step of
 * fmu/CMakeLists.txt). SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>

#include "fmu_impl.h"

int main(int argc, char *argv[])
{
    if (argc != 2) {
        fputs("usage: tirenv_fmu_describe OUT.xml\n", stderr);
        return 2;
    }
    FILE *fp = fopen(argv[1], "w");
    if (!fp) {
        perror(argv[1]);
        return 1;
    }
    const int bad = fmu__describe(fp);
    if (fclose(fp) || bad) {
        fprintf(stderr, "tirenv_fmu_describe: %s: write failed\n", argv[1]);
        remove(argv[1]);
        return 1;
    }
    return 0;
}
