/*
 * string.h - the part of <string.h> the mote core and the firmware example
 * use, for cross builds that see no C library (-nostdinc -nostdlib).
 * memcpy and memset map to the compiler's builtins so that small constant
 * copies stay inline under -ffreestanding; the out-of-line versions the
 * compiler may still call are in embedded/firmware/mini_libc.c.
 */
#ifndef MOTE_EMBEDDED_STRING_H
#define MOTE_EMBEDDED_STRING_H

#include <stddef.h>

void *memcpy(void *dst, const void *src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);

#ifndef MOTE_MINI_LIBC_IMPL
#define memcpy(d, s, n) __builtin_memcpy((d), (s), (n))
#define memset(d, c, n) __builtin_memset((d), (c), (n))
#endif

#endif
