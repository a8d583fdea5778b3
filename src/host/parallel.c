/*
 * parallel.c - the host's tile loop on OpenMP threads. This is the only
 * place OpenMP appears; built without -fopenmp it runs the tiles in order.
 * Each tile is independent and deterministic, so the schedule does not
 * change a single byte of the image.
 */
#include <mote/mote_io.h>

#ifdef _OPENMP
#include <omp.h>
#endif

void mote_parallel_openmp(void *user, int count, mote_task_fn fn, void *task_arg)
{
#ifdef _OPENMP
    int threads = user ? *(const int *)user : 0;
    if (threads <= 0)
        threads = omp_get_max_threads();
    #pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int i = 0; i < count; i++)
        fn(task_arg, i);
#else
    (void)user;
    for (int i = 0; i < count; i++)
        fn(task_arg, i);
#endif
}
