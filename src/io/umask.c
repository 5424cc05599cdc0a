/* The umask without the umask(0)/umask(mask) dance: while a thread of a parallel data-set
 * build has it at 0, another one creating a file gets mode 0666, and two threads dancing at
 * once can leave the process's umask at 0 for good. Linux (4.7 and later) shows it in
 * /proc/self/status; elsewhere the dance runs under a lock, so at least the library's own
 * threads never interleave it. SPDX-License-Identifier: Apache-2.0 */
#include "io/umask.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

mode_t tirenv_data__umask(void)
{
    FILE *fp = fopen("/proc/self/status", "r");
    if (fp) {
        char line[256];
        while (fgets(line, sizeof line, fp))
            if (strncmp(line, "Umask:", 6) == 0) {
                char *end;
                const long mask = strtol(line + 6, &end, 8);
                if (end != line + 6 && mask >= 0 && mask <= 0777) {
                    fclose(fp);
                    return (mode_t)mask;
                }
            }
        fclose(fp);
    }
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    pthread_mutex_lock(&lock);
    const mode_t mask = umask(0);
    umask(mask);
    pthread_mutex_unlock(&lock);
    return mask;
}
