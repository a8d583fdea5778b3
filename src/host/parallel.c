/*
 * parallel.c - the host's tile loop on OpenMP threads. This is the only
 * place OpenMP appears; built without -fopenmp it runs the tiles in order.
 * Each tile is independent and deterministic, so the schedule does not
 * change a single byte of the image.
 *
 * The schedule: the jobs are cut into one contiguous run per thread, each
 * thread works through its own run from the front, and a thread that has
 * finished takes jobs from the back of the others' runs, so neighbouring
 * tiles, and the clear's stripes and the tiles on them, stay on one core
 * and their cache lines need not move between cores, which schedule
 * (dynamic, 1) made them do (docs/performance.md has the figures).
 */
#include <mote/mote_io.h>

#ifdef _OPENMP
#include <omp.h>
#include <stdlib.h>
#include <string.h>

/* One thread's run of jobs. taken counts the claims on it (the owner's and
 * thieves'), back the thieves'; each in its own cache line. */
typedef struct mote__run {
    int taken;
    char pad0[60];
    int back;
    char pad1[60];
} mote__run;

static int mote__claim(int *counter)
{
    int k;
    #pragma omp atomic capture
    k = (*counter)++;
    return k;
}

/* Run r of n over count jobs holds the jobs [first(r), first(r + 1)). */
static int mote__run_first(int r, int n, int count)
{
    return (int)((long long)count * r / n);
}

static void mote__run_jobs(mote__run *runs, int nruns, int count, mote_task_fn fn, void *task_arg)
{
    /* a team may be smaller than asked: runs nobody owns are only stolen */
    const int me = omp_get_thread_num();
    const int first = mote__run_first(me, nruns, count), size = mote__run_first(me + 1, nruns, count) - first;
    /* the owner's claims and the thieves' together never exceed the run's
     * size, so the front (owner) and the back (thieves) never meet */
    for (int own = first; mote__claim(&runs[me].taken) < size; own++)
        fn(task_arg, own);
    for (int i = 1; i < nruns; i++) {
        const int v = (me + i) % nruns;
        const int start = mote__run_first(v, nruns, count), end = mote__run_first(v + 1, nruns, count);
        while (mote__claim(&runs[v].taken) < end - start)
            fn(task_arg, end - 1 - mote__claim(&runs[v].back));
    }
}
#endif

void mote_parallel_openmp(void *user, int count, mote_task_fn fn, void *task_arg)
{
#ifdef _OPENMP
    int threads = user ? *(const int *)user : 0;
    if (threads <= 0)
        threads = omp_get_max_threads();
    if (threads > count)
        threads = count;
    if (threads > 1) {
        /* a few runs on the stack; more from the heap (or one thread) */
        mote__run local[16];
        mote__run *runs = threads <= 16 ? local : (mote__run *)malloc((size_t)threads * sizeof *runs);
        if (runs) {
            memset(runs, 0, (size_t)threads * sizeof *runs);
            #pragma omp parallel num_threads(threads)
            mote__run_jobs(runs, threads, count, fn, task_arg);
            if (runs != local)
                free(runs);
            return;
        }
    }
#else
    (void)user;
#endif
    for (int i = 0; i < count; i++)
        fn(task_arg, i);
}
