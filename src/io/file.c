/*
 * file.c - files in and out of src/io. In: a file is opened first and
 * then examined on its descriptor (a regular file, never waited on), and a
 * file that a scene names is opened beneath the scene's folder as the
 * system resolves the name, symbolic links included (openat2 with
 * RESOLVE_BENEATH, else a walk one component at a time). Out: a new file is
 * written beside its target and renamed over it, so that a failed write
 * leaves the target as it was and removes nothing it did not create.
 */
#if defined(__unix__) || defined(__APPLE__)
#define MOTE__POSIX 1
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L   /* openat, readlinkat, fdopen, realpath */
#endif
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE           /* syscall(), for openat2 without a libc wrapper */
#endif
#endif

#include "io_internal.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef MOTE__POSIX
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/syscall.h>
#endif
#endif

/* Longest name a scene may give a file, and longest symbolic link read. */
#define MOTE__NAME_MAX 4096

bool mote__io_same_file(mote__io_file_id a, mote__io_file_id b)
{
    return (a.device | a.inode) != 0 && a.device == b.device && a.inode == b.inode;
}

bool mote__io_name_escapes(const char *name, const char **why)
{
    if (!name[0]) {
        *why = "is empty";
        return true;
    }
    if (name[0] == '/' || name[0] == '\\' ||
        (((name[0] | 0x20) >= 'a' && (name[0] | 0x20) <= 'z') && name[1] == ':')) {
        *why = "is an absolute path";
        return true;
    }
    const char *p = name;
    while (*p) {
        const char *q = p;
        while (*q && *q != '/' && *q != '\\')
            q++;
        if (q - p == 2 && p[0] == '.' && p[1] == '.') {
            *why = "leaves the scene's folder with '..'";
            return true;
        }
        p = *q ? q + 1 : q;
    }
    return false;
}

/* ---- reading ------------------------------------------------------------ */

#ifdef MOTE__POSIX
static const char *mote__not_regular(mode_t mode)
{
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return "a device";
    return "something else";
}

static mote__io_file_id mote__id_of(const struct stat *st)
{
    mote__io_file_id id;
    id.device = (uint64_t)st->st_dev;
    id.inode = (uint64_t)st->st_ino;
    return id;
}

/* Takes fd (opened with O_NONBLOCK, so that a FIFO did not wait for a
 * writer): a regular file becomes out's stream, anything else is refused
 * and closed. */
static mote_result mote__io_adopt(int fd, const char *name, mote__io_file *out, char *message,
                                  size_t message_size)
{
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int err = errno;
        close(fd);
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot open: %s", name,
                              strerror(err));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return mote__io_error(message, message_size, MOTE_ERR_IO,
                              "%s: cannot open: %s, not a regular file", name,
                              mote__not_regular(st.st_mode));
    }
    int flags = fcntl(fd, F_GETFL);
    FILE *f = NULL;
    if (flags != -1 && fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != -1)
        f = fdopen(fd, "rb");
    if (!f) {
        int err = errno;
        close(fd);
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot open: %s", name,
                              strerror(err));
    }
    out->stream = f;
    out->id = mote__id_of(&st);
    return MOTE_OK;
}

/* Flags of a file opened to be read: never waiting (a FIFO), never taking
 * a terminal. */
#define MOTE__READ_FLAGS (O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)
#endif

mote_result mote__io_open(const char *path, mote__io_file *out, char *message,
                          size_t message_size)
{
    memset(out, 0, sizeof *out);
    char *name = out->name;
    mote__io_clean_name(name, sizeof out->name, path);
#ifdef MOTE__POSIX
    int fd = open(path, MOTE__READ_FLAGS);
    if (fd < 0)
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot open: %s", name,
                              strerror(errno));
    return mote__io_adopt(fd, name, out, message, message_size);
#else
    /* plain C cannot tell a FIFO or a device: the size limit is the guard */
    out->stream = fopen(path, "rb");
    if (!out->stream)
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot open: %s", name,
                              strerror(errno));
    return MOTE_OK;
#endif
}

#ifdef MOTE__POSIX
static int mote__io_walk_only;

void mote__io_resolve_by_walk(int on)
{
    mote__io_walk_only = on;
}

/* Opens name beneath the folder dirfd one component at a time, each with
 * O_NOFOLLOW: a symbolic link is read and its target put in its place, a
 * ".." steps back to the folder held before, and an absolute target, or a
 * ".." above dirfd, fails with EXDEV, as RESOLVE_BENEATH does. The
 * folders on the way are held open, so that renaming them meanwhile
 * cannot lead outside. -1 with errno on failure. */
static int mote__open_by_walk(int dirfd, const char *name, int flags)
{
    enum { DEPTH = 64, LINKS = 40 };  /* 40: Linux's limit on links in a path */
    int held[DEPTH + 1], depth = 0, links = 0, fd = -1;
    char rest[MOTE__NAME_MAX], target[MOTE__NAME_MAX];
    held[0] = dirfd;
    size_t n = strlen(name);
    if (n >= sizeof rest) {
        errno = ENAMETOOLONG;
        return -1;
    }
    memcpy(rest, name, n + 1);
    const char *p = rest;
    for (;;) {
        while (*p == '/')
            p++;
        size_t len = strcspn(p, "/");
        const char *after = p + len;
        while (*after == '/')
            after++;
        bool last = *after == '\0';
        /* "name/" names a folder, as the kernel reads it: a file there
         * fails with ENOTDIR */
        const int last_flags = flags | (after > p + len ? O_DIRECTORY : 0);
        char part[256];
        if (len == 0 || (len == 1 && p[0] == '.') || (len == 2 && p[0] == '.' && p[1] == '.')) {
            if (len == 2 && depth == 0) {
                errno = EXDEV;
                break;
            }
            if (len == 2)
                close(held[depth--]);
            if (len == 0 || last) {
                errno = EISDIR;       /* the name ends at a folder */
                break;
            }
            p = after;
            continue;
        }
        if (len >= sizeof part) {
            errno = ENAMETOOLONG;
            break;
        }
        memcpy(part, p, len);
        part[len] = '\0';
        int f = openat(held[depth], part,
                       (last ? last_flags : O_RDONLY | O_DIRECTORY | O_CLOEXEC) | O_NOFOLLOW);
        if (f >= 0 && last) {
            fd = f;
            break;
        }
        if (f >= 0) {
            if (depth == DEPTH) {
                close(f);
                errno = ENAMETOOLONG;
                break;
            }
            held[++depth] = f;
            p = after;
            continue;
        }
        /* O_NOFOLLOW met a link: ELOOP (EMLINK on FreeBSD; ENOTDIR where
         * a folder was asked for) */
        int open_errno = errno;
        if (open_errno != ELOOP && open_errno != EMLINK && open_errno != ENOTDIR)
            break;
        ssize_t tn = readlinkat(held[depth], part, target, sizeof target);
        if (tn < 0) {
            errno = errno == EINVAL ? open_errno : errno;   /* EINVAL: not a link */
            break;
        }
        if ((size_t)tn >= sizeof target || ++links > LINKS) {
            errno = (size_t)tn >= sizeof target ? ENAMETOOLONG : ELOOP;
            break;
        }
        if (tn == 0 || target[0] == '/') {
            errno = tn == 0 ? ENOENT : EXDEV;
            break;
        }
        size_t an = strlen(after);
        if ((size_t)tn + 1 + an >= sizeof rest) {
            errno = ENAMETOOLONG;
            break;
        }
        /* the target, then what followed the link (after lies in rest);
         * a slash only between them, or "link/" would stay a folder's name
         * and "link" become one */
        const size_t sep = an || after > p + len ? 1 : 0;
        memmove(rest + tn + sep, after, an + 1);
        memcpy(rest, target, (size_t)tn);
        if (sep)
            rest[tn] = '/';
        p = rest;
    }
    int err = errno;
    while (depth > 0)
        close(held[depth--]);
    errno = err;
    return fd;
}

/* openat2(dirfd, name, RESOLVE_BENEATH | RESOLVE_NO_MAGICLINKS), or the
 * walk where the kernel (before Linux 5.6), a seccomp filter or
 * mote__io_resolve_by_walk say no. */
static int mote__open_beneath(int dirfd, const char *name, int flags)
{
#if defined(__linux__) && defined(SYS_openat2)
    if (!mote__io_walk_only) {
        /* struct open_how of <linux/openat2.h>, a fixed kernel ABI */
        struct {
            uint64_t flags, mode, resolve;
        } how = {(uint64_t)(unsigned)flags, 0, 0x08 /* BENEATH */ | 0x02 /* NO_MAGICLINKS */};
        for (int tries = 0; tries < 16; tries++) {
            long fd = syscall(SYS_openat2, dirfd, name, &how, sizeof how);
            if (fd >= 0)
                return (int)fd;
            if (errno != EAGAIN)     /* EAGAIN: a rename raced the walk up */
                break;
        }
        if (errno != ENOSYS && errno != EPERM && errno != EINVAL && errno != E2BIG)
            return -1;
    }
#endif
    return mote__open_by_walk(dirfd, name, flags);
}
#else
void mote__io_resolve_by_walk(int on)
{
    (void)on;
}
#endif

mote_result mote__io_open_in_folder(const char *folder, const char *name, bool anywhere,
                                    mote__io_file *out, char *message, size_t message_size)
{
    memset(out, 0, sizeof *out);
    const char *why = "";
    if (!anywhere && mote__io_name_escapes(name, &why)) {
        char quoted[72];
        mote__io_clean_name(quoted, sizeof quoted, name);
        return mote__io_error(message, message_size, MOTE_ERR_RANGE, "\"%s\" %s", quoted, why);
    }
    size_t nlen = strlen(name), flen = folder ? strlen(folder) : 0;
    bool absolute = name[0] == '/' || name[0] == '\\';
    if (nlen >= MOTE__NAME_MAX || flen >= MOTE__NAME_MAX) {
        char quoted[72];
        mote__io_clean_name(quoted, sizeof quoted, name);
        return mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                              "\"%s\": a name of %zu bytes, longer than %d", quoted, nlen,
                              MOTE__NAME_MAX - 1);
    }
    /* the name as opened, and folder/name for messages */
    char relative[MOTE__NAME_MAX], joined[2 * MOTE__NAME_MAX + 2];
    memcpy(relative, name, nlen + 1);
#ifndef _WIN32
    for (char *c = relative; *c; c++)
        if (*c == '\\')
            *c = '/';                 /* exporters on Windows write folder\\image.png */
#endif
    if (absolute || flen == 0)
        memcpy(joined, relative, nlen + 1);
    else
        snprintf(joined, sizeof joined, "%s/%s", folder, relative);
    char *shown = out->name;
    mote__io_clean_name(shown, sizeof out->name, joined);
#ifdef MOTE__POSIX
    int dirfd = open(flen ? folder : ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dirfd < 0)
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot open: %s", shown,
                              strerror(errno));
    int fd = anywhere ? openat(dirfd, relative, MOTE__READ_FLAGS)
                      : mote__open_beneath(dirfd, relative, MOTE__READ_FLAGS);
    int err = errno;
    close(dirfd);
    if (fd < 0 && err == EXDEV) {
        char quoted[72];
        mote__io_clean_name(quoted, sizeof quoted, name);
        return mote__io_error(message, message_size, MOTE_ERR_RANGE,
                              "\"%s\" leads out of the scene's folder through a symbolic link",
                              quoted);
    }
    if (fd < 0)
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot open: %s", shown,
                              strerror(err));
    return mote__io_adopt(fd, shown, out, message, message_size);
#else
    return mote__io_open(joined, out, message, message_size);
#endif
}

void mote__io_close(mote__io_file *file)
{
    if (file->stream)
        fclose(file->stream);
    file->stream = NULL;
}

mote_result mote__io_read_open(mote__io_file *file, size_t max_bytes, char **data, size_t *size,
                               char *message, size_t message_size)
{
    *data = NULL;
    *size = 0;
    const char *name = file->name;
    FILE *f = file->stream;
    /* Read in chunks rather than trusting the file's size: the limit is
     * enforced on the bytes actually read. */
    size_t cap = 0, len = 0;
    char *buf = NULL;
    mote_result r = MOTE_OK;
    for (;;) {
        if (len == cap) {
            if (cap > max_bytes) {
                r = mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                                   "%s: file is larger than the limit of %zu bytes", name,
                                   max_bytes);
                break;
            }
            /* one byte past the limit tells a file over it; a limit of
             * SIZE_MAX (no limit) must not wrap that to 0 */
            size_t ncap = cap ? cap * 2 : 65536;
            if (max_bytes < SIZE_MAX - 1 && ncap > max_bytes + 1)
                ncap = max_bytes + 1;
            char *nb = cap <= SIZE_MAX / 4 ? mote__io_malloc(ncap + 1) : NULL;
            if (!nb) {
                r = mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                                   "%s: out of memory reading %zu bytes", name, ncap);
                break;
            }
            if (len)
                memcpy(nb, buf, len);
            mote__io_free(buf);
            buf = nb;
            cap = ncap;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0) {
            if (ferror(f))
                r = mote__io_error(message, message_size, MOTE_ERR_IO, "%s: read error", name);
            break;
        }
    }
    mote__io_close(file);
    if (r == MOTE_OK && len > max_bytes)
        r = mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                           "%s: file is larger than the limit of %zu bytes", name, max_bytes);
    if (r != MOTE_OK) {
        mote__io_free(buf);
        return r;
    }
    if (!buf) {
        buf = mote__io_malloc(1);
        if (!buf)
            return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                                  "%s: out of memory", name);
    }
    buf[len] = '\0';
    *data = buf;
    *size = len;
    return MOTE_OK;
}

mote_result mote__io_read_file(const char *path, size_t max_bytes, char **data, size_t *size,
                               char *message, size_t message_size)
{
    *data = NULL;
    *size = 0;
    mote__io_file file;
    mote_result r = mote__io_open(path, &file, message, message_size);
    if (r != MOTE_OK)
        return r;
    return mote__io_read_open(&file, max_bytes, data, size, message, message_size);
}

mote__io_file_id mote__io_file_id_of(const char *path)
{
    mote__io_file_id id = {0, 0};
#ifdef MOTE__POSIX
    struct stat st;
    if (path && stat(path, &st) == 0)
        id = mote__id_of(&st);
#else
    (void)path;
#endif
    return id;
}

bool mote_scene_reads_file(const mote_scene *scene, const char *path)
{
    if (!scene || !scene->files_ || !path)
        return false;
    const mote__scene_files *files = scene->files_;
    const mote__io_file_id id = mote__io_file_id_of(path);
    if (mote__io_same_file(files->scene, id))
        return true;
    for (int i = 0; files->textures && i < scene->texture_count; i++)
        if (mote__io_same_file(files->textures[i], id))
            return true;
    return false;
}

/* ---- writing ------------------------------------------------------------ */

#ifdef MOTE__POSIX
/* A name for a new file beside target: ".NAME.PID-N.tmp" in its folder. */
static char *mote__temp_name(const char *target, unsigned long n)
{
    const char *slash = strrchr(target, '/');
    size_t dir_len = slash ? (size_t)(slash - target) + 1 : 0;
    size_t size = strlen(target) + 64;
    char *t = mote__io_malloc(size);
    if (t)
        snprintf(t, size, "%.*s.%s.%ld-%lu.tmp", (int)dir_len, target,
                 slash ? slash + 1 : target, (long)getpid(), n);
    return t;
}

/* Creates the temporary file beside out->target, as no one else's file:
 * O_EXCL, and a name not yet taken. */
static mote_result mote__create_temp(mote__io_output *out, const struct stat *old,
                                     const char *name, char *message, size_t message_size)
{
    static unsigned long counter;
    for (int tries = 0; tries < 100; tries++) {
#if defined(__GNUC__)
        unsigned long n = __atomic_add_fetch(&counter, 1, __ATOMIC_RELAXED);
#else
        unsigned long n = ++counter;
#endif
        out->temp = mote__temp_name(out->target, n);
        if (!out->temp)
            return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                                  "%s: out of memory", name);
        int fd = open(out->temp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0) {
            /* a file replaced keeps its permissions */
            if (old)
                (void)fchmod(fd, old->st_mode & 07777);
            out->stream = fdopen(fd, "wb");
            if (out->stream)
                return MOTE_OK;
            int err = errno;
            close(fd);
            unlink(out->temp);
            errno = err;
        }
        int err = errno;
        mote__io_free(out->temp);
        out->temp = NULL;
        if (fd < 0 && err == EEXIST)
            continue;
        return mote__io_error(message, message_size, MOTE_ERR_IO,
                              "%s: cannot create (a new file beside it): %s", name,
                              strerror(err));
    }
    return mote__io_error(message, message_size, MOTE_ERR_IO,
                          "%s: cannot create: no free name for a new file beside it", name);
}
#endif

mote_result mote__io_output_open(const char *path, mote__io_output *out, char *message,
                                 size_t message_size)
{
    memset(out, 0, sizeof *out);
    char name[160];
    mote__io_clean_name(name, sizeof name, path);
#ifdef MOTE__POSIX
    struct stat st;
    if (lstat(path, &st) != 0) {
        if (errno != ENOENT)
            return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot create: %s",
                                  name, strerror(errno));
        size_t n = strlen(path) + 1;      /* a new file */
        out->target = mote__io_malloc(n);
        if (!out->target)
            return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                                  "%s: out of memory", name);
        memcpy(out->target, path, n);
        mote_result r = mote__create_temp(out, NULL, name, message, message_size);
        if (r != MOTE_OK)
            mote__io_output_discard(out);
        return r;
    }
    bool link = S_ISLNK(st.st_mode);
    if (link && stat(path, &st) != 0)
        return mote__io_error(message, message_size, MOTE_ERR_IO,
                              "%s: not written: a symbolic link to nothing (%s)", name,
                              strerror(errno));
    if (S_ISREG(st.st_mode)) {
        /* replaced where it is: through a link, the file the link names */
        char *real = link ? realpath(path, NULL) : NULL;
        if (link && !real)
            return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot create: %s",
                                  name, strerror(errno));
        const char *target = real ? real : path;
        size_t n = strlen(target) + 1;
        out->target = mote__io_malloc(n);
        if (out->target)
            memcpy(out->target, target, n);
        free(real);
        if (!out->target)
            return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                                  "%s: out of memory", name);
        mote_result r = mote__create_temp(out, &st, name, message, message_size);
        if (r != MOTE_OK)
            mote__io_output_discard(out);
        return r;
    }
    if (!S_ISCHR(st.st_mode) && !S_ISFIFO(st.st_mode))
        return mote__io_error(message, message_size, MOTE_ERR_IO,
                              "%s: not written: %s, not a regular file", name,
                              S_ISDIR(st.st_mode) ? "a directory"
                              : S_ISBLK(st.st_mode) ? "a block device" : "something else");
    /* A terminal, /dev/null or a pipe is written in place, and never
     * removed: a FIFO no one reads is refused rather than waited on. */
    int fd = open(path, O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot write: %s", name,
                              errno == ENXIO ? "a FIFO that no one reads" : strerror(errno));
    int flags = fcntl(fd, F_GETFL);
    if (fstat(fd, &st) != 0 || (!S_ISCHR(st.st_mode) && !S_ISFIFO(st.st_mode)) || flags == -1 ||
        fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == -1 || !(out->stream = fdopen(fd, "wb"))) {
        close(fd);
        return mote__io_error(message, message_size, MOTE_ERR_IO,
                              "%s: not written: it changed while it was opened", name);
    }
    return MOTE_OK;
#else
    out->stream = fopen(path, "wb");
    if (!out->stream)
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot create: %s", name,
                              strerror(errno));
    return MOTE_OK;
#endif
}

void mote__io_output_discard(mote__io_output *out)
{
    if (out->stream)
        fclose(out->stream);
    if (out->temp)
        remove(out->temp);        /* the new file, never the target */
    mote__io_free(out->temp);
    mote__io_free(out->target);
    memset(out, 0, sizeof *out);
}

mote_result mote__io_output_close(mote__io_output *out, bool ok, const char *path,
                                  char *message, size_t message_size)
{
    char name[160];
    mote__io_clean_name(name, sizeof name, path);
    int err = ok ? 0 : errno;     /* why the write failed, before fclose changes it */
    FILE *f = out->stream;
    out->stream = NULL;
    if (fclose(f) != 0 && ok) {
        err = errno;
        ok = false;
    }
    if (ok && out->temp && rename(out->temp, out->target) != 0) {
        mote__io_error(message, message_size, MOTE_ERR_IO,
                       "%s: cannot put the new file in its place: %s", name, strerror(errno));
        mote__io_output_discard(out);
        return MOTE_ERR_IO;
    }
    if (ok) {
        mote__io_free(out->temp);
        out->temp = NULL;
    }
    mote__io_output_discard(out);
    if (!ok)
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: write error%s%s", name,
                              err ? ": " : "", err ? strerror(err) : "");
    return MOTE_OK;
}

mote_result mote_write_file(const char *path, const void *data, size_t size, char *message,
                            size_t message_size)
{
    if (!path || (!data && size > 0))
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "write file: no path or no data given");
    mote__io_output out;
    mote_result r = mote__io_output_open(path, &out, message, message_size);
    if (r != MOTE_OK)
        return r;
    bool ok = size == 0 || fwrite(data, 1, size, out.stream) == size;
    return mote__io_output_close(&out, ok, path, message, message_size);
}
