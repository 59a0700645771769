/*
 * Work shared between POSIX threads for the multi-threaded entry points. The calling thread works
 * too, items are handed out one at a time under a mutex (patches differ in cost), and every thread
 * is joined before returning, so no thread outlives a call. Results never depend on the threads:
 * each item writes its own part of the outputs.
 */
#include "core/internal.h"

#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>

/* More workers than this are never started, whatever the caller asks. */
#define MAX_WORKERS ((size_t)256)

size_t bsi_thread_count(size_t threads, size_t items)
{
    if (threads == 0) {
        long cpus = sysconf(_SC_NPROCESSORS_ONLN);
        threads = cpus > 0 ? (size_t)cpus : 1;
    }
    if (threads > MAX_WORKERS)
        threads = MAX_WORKERS;
    if (threads > items)
        threads = items;
    return threads ? threads : 1;
}

typedef struct shared {
    pthread_mutex_t lock;
    bsi_task fn;
    void *ctx;
    size_t n, next;
    size_t failed;    /* lowest failing item, n when none */
    bs_status status; /* its status */
} shared;

typedef struct worker { shared *sh; size_t index; } worker;

/* Take items until none is left or one has failed. */
static void work(shared *sh, size_t index)
{
    for (;;) {
        pthread_mutex_lock(&sh->lock);
        size_t item = sh->failed < sh->n ? sh->n : sh->next;
        if (item < sh->n)
            sh->next++;
        pthread_mutex_unlock(&sh->lock);
        if (item >= sh->n)
            return;
        bs_status st = sh->fn(sh->ctx, item, index);
        if (st != BS_OK) {
            pthread_mutex_lock(&sh->lock);
            if (item < sh->failed) {
                sh->failed = item;
                sh->status = st;
            }
            pthread_mutex_unlock(&sh->lock);
        }
    }
}

static void *thread_main(void *arg)
{
    worker *w = arg;
    work(w->sh, w->index);
    return NULL;
}

/* Every item on the calling thread, in order. */
static bs_status serial(size_t n, bsi_task fn, void *ctx)
{
    for (size_t i = 0; i < n; i++) {
        bs_status st = fn(ctx, i, 0);
        if (st != BS_OK)
            return st;
    }
    return BS_OK;
}

bs_status bsi_parallel(size_t workers, size_t n, bsi_task fn, void *ctx)
{
    if (workers > MAX_WORKERS)
        workers = MAX_WORKERS;
    if (workers <= 1 || n <= 1)
        return serial(n, fn, ctx);
    shared sh = {.fn = fn, .ctx = ctx, .n = n, .next = 0, .failed = n, .status = BS_OK};
    if (pthread_mutex_init(&sh.lock, NULL) != 0)
        return serial(n, fn, ctx);
    pthread_t tid[MAX_WORKERS];
    worker w[MAX_WORKERS];
    size_t started = 0;
    /* worker indices stay below `workers` even when some threads could not be created */
    for (size_t k = 1; k < workers; k++) {
        w[started].sh = &sh;
        w[started].index = started + 1;
        if (pthread_create(&tid[started], NULL, thread_main, &w[started]) != 0)
            break; /* no more threads now: the calling thread and those started do the rest */
        started++;
    }
    work(&sh, 0);
    for (size_t k = 0; k < started; k++)
        pthread_join(tid[k], NULL);
    pthread_mutex_destroy(&sh.lock);
    return sh.failed < n ? sh.status : BS_OK;
}
