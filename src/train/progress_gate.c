/* One progress callback shared by trainings that run at once (tirenv/train.h): a lock makes
 * its calls one at a time, and a flag keeps its request to stop for every training.
 * SPDX-License-Identifier: Apache-2.0 */
#include <pthread.h>
#include <stdlib.h>

#include "tirenv/train.h"

struct tirenv_train_progress_gate {
    tirenv_train_progress_fn fn;
    void *data;
    pthread_mutex_t lock;
    int stop;
};

static int gated_progress(const tirenv_train_progress *p, void *data)
{
    tirenv_train_progress_gate *g = data;
    pthread_mutex_lock(&g->lock);
    if (!g->stop && g->fn(p, g->data))
        g->stop = 1;
    const int stop = g->stop;
    pthread_mutex_unlock(&g->lock);
    return stop;
}

tirenv_train_progress_gate *tirenv_train_progress_gate_alloc(tirenv_train_settings *s)
{
    tirenv_train_progress_gate *g = malloc(sizeof *g);
    if (!g)
        return NULL;
    if (pthread_mutex_init(&g->lock, NULL) != 0) {
        free(g);
        return NULL;
    }
    g->fn = s->progress;
    g->data = s->progress_data;
    g->stop = 0;
    if (s->progress) {
        s->progress = gated_progress;
        s->progress_data = g;
    }
    return g;
}

void tirenv_train_progress_gate_free(tirenv_train_progress_gate *g)
{
    if (!g)
        return;
    pthread_mutex_destroy(&g->lock);
    free(g);
}
