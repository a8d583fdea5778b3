/*
 * pool.c - a persistent pool of threads for desc.parallel_for, in which
 * the calling thread works too and a call returns as soon as its tasks
 * are done. A thread the system has put aside (another process busy on
 * its core) is not waited for: when it runs again it finds no task left
 * and goes back to sleep. An OpenMP parallel region instead ends at a
 * join that waits for every thread of the team, however late.
 *
 * The schedule is parallel.c's: the tasks are cut into one run per
 * thread, each thread takes its own run from the front and then the
 * others' from the back. Each run is one 64-bit word, its call's number
 * (32 bits) and the front and end of what is left (16 bits each), taken
 * by compare-and-swap: a thread still holding a finished call's number
 * takes nothing from the next call. Tasks are independent and
 * deterministic, so the schedule changes no byte of the image.
 */
#if !defined(_WIN32)
#define _POSIX_C_SOURCE 200809L
#endif

#include "../io/io_internal.h"

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#if !defined(_WIN32)
#include <errno.h>
#include <pthread.h>
#include <time.h>
#include <unistd.h>
#define MOTE__POOL_THREADS 1
#else
#define MOTE__POOL_THREADS 0
#endif

/* More threads than this are refused: a bound on the runs' words. */
#define MOTE__POOL_MAX 4096
/* A run's front and end are 16 bits: a call of more tasks than the
 * threads' runs hold goes as several steps. */
#define MOTE__RUN_MAX 65535u

#if MOTE__POOL_THREADS

typedef struct mote__slot {
    uint64_t word;                /* call number << 32 | front << 16 | end */
    char pad[56];
} mote__slot;

struct mote_pool {
    mote__slot *runs;             /* threads of them, each in its own line */
    void *runs_mem;
    pthread_t *workers;           /* threads - 1: thread 0 is the caller */
    int threads, started;
    void (*on_wake)(void *user, int thread);
    void *user;
    pthread_mutex_t lock;
    pthread_cond_t wake, finished;
    uint32_t step;                /* the current call's number: written under lock, read atomically */
    int sleepers;                 /* under lock */
    bool quit, caller_waiting;    /* under lock */
    int busy;                     /* atomic: a call in progress (another caller runs serially) */
    /* the step, written before its runs are opened, read after a task is taken */
    mote_task_fn fn;
    void *arg;
    int base, count;
    char pad[64];
    uint32_t done;                /* atomic: tasks of this step finished */
};

static inline void mote__pause(void)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    __builtin_ia32_pause();
#elif defined(__GNUC__) && defined(__aarch64__)
    __asm__ __volatile__("yield");
#endif
}

/* Spinning keeps a woken thread quick between a frame's steps, but takes
 * a core from whoever else wants it: a short while, then sleep. */
#define MOTE__SPIN_NS 30000L

static long long mote__now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000000000LL + t.tv_nsec;
}

/* Spins until *p == v is until (true), or the spin's time is over (false). */
static bool mote__spin(const uint32_t *p, uint32_t v, bool until)
{
    long long end = 0;
    for (int i = 0;; i++) {
        if ((__atomic_load_n(p, __ATOMIC_ACQUIRE) == v) == until)
            return true;
        if ((i & 63) == 63) {
            long long now = mote__now_ns();
            if (!end)
                end = now + MOTE__SPIN_NS;
            else if (now >= end)
                return false;
        }
        mote__pause();
    }
}

static int mote__run_first(const mote_pool *pool, int r)
{
    return (int)((long long)pool->count * r / pool->threads);
}

/* Takes a task of run r in call n: from the front (its owner) or the back
 * (a thief). Returns its index in the run, or -1 when none is left. */
static int mote__take(mote__slot *run, uint32_t n, bool front)
{
    uint64_t cur = __atomic_load_n(&run->word, __ATOMIC_ACQUIRE);
    for (;;) {
        uint32_t f = (uint32_t)(cur >> 16) & 0xffffu, e = (uint32_t)cur & 0xffffu;
        if ((uint32_t)(cur >> 32) != n || f >= e)
            return -1;
        uint64_t next = front ? cur + (1u << 16) : cur - 1u;
        if (__atomic_compare_exchange_n(&run->word, &cur, next, true, __ATOMIC_ACQUIRE, __ATOMIC_ACQUIRE))
            return (int)(front ? f : e - 1u);
    }
}

/* Runs task i of run r (the call is live: one of its tasks is ours). */
static void mote__do(mote_pool *pool, int r, int i)
{
    const uint32_t count = (uint32_t)pool->count;
    pool->fn(pool->arg, pool->base + mote__run_first(pool, r) + i);
    if (__atomic_add_fetch(&pool->done, 1u, __ATOMIC_ACQ_REL) == count) {
        pthread_mutex_lock(&pool->lock);
        if (pool->caller_waiting)
            pthread_cond_broadcast(&pool->finished);
        pthread_mutex_unlock(&pool->lock);
    }
}

static void mote__work(mote_pool *pool, uint32_t n, int me)
{
    for (int i; (i = mote__take(&pool->runs[me], n, true)) >= 0;)
        mote__do(pool, me, i);
    for (int k = 1; k < pool->threads; k++) {
        const int v = (me + k) % pool->threads;
        for (int i; (i = mote__take(&pool->runs[v], n, false)) >= 0;)
            mote__do(pool, v, i);
    }
}

typedef struct mote__worker_arg {
    mote_pool *pool;
    int me;
} mote__worker_arg;

static void *mote__worker(void *p)
{
    mote_pool *pool = ((mote__worker_arg *)p)->pool;
    const int me = ((mote__worker_arg *)p)->me;
    mote__io_free(p);
    uint32_t seen = __atomic_load_n(&pool->step, __ATOMIC_ACQUIRE);
    for (;;) {
        if (!mote__spin(&pool->step, seen, false)) {
            pthread_mutex_lock(&pool->lock);
            pool->sleepers++;
            while (!pool->quit && __atomic_load_n(&pool->step, __ATOMIC_ACQUIRE) == seen)
                pthread_cond_wait(&pool->wake, &pool->lock);
            pool->sleepers--;
            bool quit = pool->quit;
            pthread_mutex_unlock(&pool->lock);
            if (quit)
                return NULL;
        }
        seen = __atomic_load_n(&pool->step, __ATOMIC_ACQUIRE);
        if (pool->on_wake)
            pool->on_wake(pool->user, me);
        mote__work(pool, seen, me);
    }
}

/* One step: tasks [base, base + count), at most MOTE__RUN_MAX a run. */
static void mote__pool_step(mote_pool *pool, int base, int count, mote_task_fn fn, void *arg)
{
    pool->fn = fn;
    pool->arg = arg;
    pool->base = base;
    pool->count = count;
    __atomic_store_n(&pool->done, 0u, __ATOMIC_RELAXED);
    const uint32_t n = pool->step + 1u;   /* only the caller writes it */
    for (int r = 0; r < pool->threads; r++) {
        uint64_t size = (uint64_t)(mote__run_first(pool, r + 1) - mote__run_first(pool, r));
        __atomic_store_n(&pool->runs[r].word, (uint64_t)n << 32 | size, __ATOMIC_RELEASE);
    }
    pthread_mutex_lock(&pool->lock);
    __atomic_store_n(&pool->step, n, __ATOMIC_RELEASE);
    if (pool->sleepers)
        pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    mote__work(pool, n, 0);
    /* what is left is running on other threads: wait for it, asleep soon,
     * so that the system may give this core to a thread it put aside */
    if (mote__spin(&pool->done, (uint32_t)count, true))
        return;
    pthread_mutex_lock(&pool->lock);
    pool->caller_waiting = true;
    while (__atomic_load_n(&pool->done, __ATOMIC_ACQUIRE) != (uint32_t)count)
        pthread_cond_wait(&pool->finished, &pool->lock);
    pool->caller_waiting = false;
    pthread_mutex_unlock(&pool->lock);
}

static void mote__pool_stop(mote_pool *pool)
{
    pthread_mutex_lock(&pool->lock);
    pool->quit = true;
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    for (int i = 0; i < pool->started; i++)
        pthread_join(pool->workers[i], NULL);
}

mote_result mote_pool_create(const mote_pool_desc *desc, mote_pool **out, char *message, size_t message_size)
{
    if (!out)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT, "mote_pool_create: out is NULL");
    *out = NULL;
    mote_pool_desc d;
    memset(&d, 0, sizeof d);
    if (desc)
        d = *desc;
    if (d.threads < 0 || d.threads > MOTE__POOL_MAX)
        return mote__io_error(message, message_size, MOTE_ERR_RANGE,
                              "mote_pool_create: threads %d is outside [0, %d]", d.threads, MOTE__POOL_MAX);
    if (d.threads == 0) {
        long online = sysconf(_SC_NPROCESSORS_ONLN);
        d.threads = online < 1 ? 1 : online > MOTE__POOL_MAX ? MOTE__POOL_MAX : (int)online;
    }
    mote_pool *pool = (mote_pool *)mote__io_calloc(1, sizeof *pool);
    if (!pool)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY, "mote_pool_create: out of memory");
    pool->threads = d.threads;
    pool->on_wake = d.on_wake;
    pool->user = d.user;
    pool->runs_mem = mote__io_calloc((size_t)d.threads + 1u, sizeof(mote__slot));
    pool->workers = d.threads > 1 ? (pthread_t *)mote__io_calloc((size_t)d.threads - 1u, sizeof(pthread_t)) : NULL;
    if (!pool->runs_mem || (d.threads > 1 && !pool->workers)) {
        mote__io_free(pool->runs_mem);
        mote__io_free(pool->workers);
        mote__io_free(pool);
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY, "mote_pool_create: out of memory");
    }
    uintptr_t at = ((uintptr_t)pool->runs_mem + 63u) & ~(uintptr_t)63u;
    pool->runs = (mote__slot *)(void *)at;
    pthread_mutex_init(&pool->lock, NULL);
    pthread_cond_init(&pool->wake, NULL);
    pthread_cond_init(&pool->finished, NULL);
    int err = 0;
    for (int i = 1; i < d.threads && !err; i++) {
        mote__worker_arg *wa = (mote__worker_arg *)mote__io_malloc(sizeof *wa);
        if (!wa) {
            err = ENOMEM;
            break;
        }
        wa->pool = pool;
        wa->me = i;
        err = pthread_create(&pool->workers[i - 1], NULL, mote__worker, wa);
        if (err)
            mote__io_free(wa);
        else
            pool->started++;
    }
    if (err) {
        int started = pool->started;
        mote_pool_destroy(pool);
        return mote__io_error(message, message_size, err == ENOMEM ? MOTE_ERR_OUT_OF_MEMORY : MOTE_ERR_IO,
                              "mote_pool_create: thread %d of %d: %s", started + 2, d.threads,
                              err == ENOMEM ? "out of memory" : "the system refused a thread");
    }
    *out = pool;
    return MOTE_OK;
}

void mote_pool_destroy(mote_pool *pool)
{
    if (!pool)
        return;
    mote__pool_stop(pool);
    pthread_cond_destroy(&pool->finished);
    pthread_cond_destroy(&pool->wake);
    pthread_mutex_destroy(&pool->lock);
    mote__io_free(pool->workers);
    mote__io_free(pool->runs_mem);
    mote__io_free(pool);
}

int mote_pool_threads(const mote_pool *pool)
{
    return pool ? pool->threads : 1;
}

void mote_parallel_pool(void *user, int count, mote_task_fn fn, void *task_arg)
{
    mote_pool *pool = (mote_pool *)user;
    int expect = 0;
    if (!pool || pool->threads < 2 || count < 2
        || !__atomic_compare_exchange_n(&pool->busy, &expect, 1, false, __ATOMIC_ACQUIRE, __ATOMIC_RELAXED)) {
        for (int i = 0; i < count; i++)
            fn(task_arg, i);
        return;
    }
    const long long cap = (long long)pool->threads * MOTE__RUN_MAX;
    for (long long base = 0; base < count; base += cap)
        mote__pool_step(pool, (int)base, (int)(count - base < cap ? count - base : cap), fn, task_arg);
    __atomic_store_n(&pool->busy, 0, __ATOMIC_RELEASE);
}

#else /* no threads here: the pool runs its tasks on the calling thread */

struct mote_pool {
    int threads;
};

mote_result mote_pool_create(const mote_pool_desc *desc, mote_pool **out, char *message, size_t message_size)
{
    if (!out)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT, "mote_pool_create: out is NULL");
    *out = (mote_pool *)mote__io_calloc(1, sizeof **out);
    if (!*out)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY, "mote_pool_create: out of memory");
    (void)desc;
    (*out)->threads = 1;
    return MOTE_OK;
}

void mote_pool_destroy(mote_pool *pool)
{
    mote__io_free(pool);
}

int mote_pool_threads(const mote_pool *pool)
{
    return pool ? pool->threads : 1;
}

void mote_parallel_pool(void *user, int count, mote_task_fn fn, void *task_arg)
{
    (void)user;
    for (int i = 0; i < count; i++)
        fn(task_arg, i);
}

#endif
