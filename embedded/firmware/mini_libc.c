/*
 * mini_libc.c - memcpy, memmove, memset and memcmp for the cross builds,
 * which link no C library (-nostdlib, libgcc only). The compiler calls these
 * for struct copies and clears even in freestanding code, and the core
 * fills each band's clear colour and depth with memcpy. memcpy and memset
 * move aligned words wherever the addresses allow (for memcpy: source and
 * destination equally aligned), four at a time, and bytes at the ends;
 * memmove and memcmp stay byte loops. Built with
 * -fno-tree-loop-distribute-patterns, which keeps GCC from turning these
 * loops into calls to themselves.
 */
#define MOTE_MINI_LIBC_IMPL
#include <stdint.h>
#include <string.h>

/* a word that may alias whatever the bytes belong to */
typedef uint32_t __attribute__((may_alias)) alias_word;

#define WORD_MASK (sizeof(alias_word) - 1)

void *memcpy(void *dst, const void *src, size_t n)
{
    unsigned char *d = dst;
    const unsigned char *s = src;
    if (n >= sizeof(alias_word) && (((uintptr_t)d ^ (uintptr_t)s) & WORD_MASK) == 0) {
        for (; (uintptr_t)d & WORD_MASK; n--)
            *d++ = *s++;
        alias_word *wd = (alias_word *)(void *)d;
        const alias_word *ws = (const alias_word *)(const void *)s;
        for (; n >= 4 * sizeof(alias_word); n -= 4 * sizeof(alias_word), wd += 4, ws += 4) {
            wd[0] = ws[0];
            wd[1] = ws[1];
            wd[2] = ws[2];
            wd[3] = ws[3];
        }
        for (; n >= sizeof(alias_word); n -= sizeof(alias_word))
            *wd++ = *ws++;
        d = (unsigned char *)wd;
        s = (const unsigned char *)ws;
    }
    while (n--)
        *d++ = *s++;
    return dst;
}

void *memmove(void *dst, const void *src, size_t n)
{
    unsigned char *d = dst;
    const unsigned char *s = src;
    if (d < s) {
        while (n--)
            *d++ = *s++;
    } else {
        while (n--)
            d[n] = s[n];
    }
    return dst;
}

void *memset(void *dst, int c, size_t n)
{
    unsigned char *d = dst;
    unsigned char byte = (unsigned char)c;
    if (n >= sizeof(alias_word)) {
        for (; (uintptr_t)d & WORD_MASK; n--)
            *d++ = byte;
        alias_word *wd = (alias_word *)(void *)d;
        uint32_t v = byte * 0x01010101u;
        for (; n >= 4 * sizeof(alias_word); n -= 4 * sizeof(alias_word), wd += 4) {
            wd[0] = v;
            wd[1] = v;
            wd[2] = v;
            wd[3] = v;
        }
        for (; n >= sizeof(alias_word); n -= sizeof(alias_word))
            *wd++ = v;
        d = (unsigned char *)wd;
    }
    while (n--)
        *d++ = byte;
    return dst;
}

int memcmp(const void *a, const void *b, size_t n)
{
    const unsigned char *p = a, *q = b;
    for (; n; n--, p++, q++)
        if (*p != *q)
            return *p < *q ? -1 : 1;
    return 0;
}
