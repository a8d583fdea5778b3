/* util.c - what the firmware example and its fake LCD share: numbers as
 * text through fw_puts (no printf here), and the frame hash. */
#include "platform.h"

void fw_put_uint(const char *label, uint32_t v, int base)
{
    char buf[16];
    int n = sizeof buf - 1;
    buf[n] = '\0';
    do {
        buf[--n] = "0123456789abcdef"[v % (uint32_t)base];
        v /= (uint32_t)base;
    } while ((v || (base == 16 && n > (int)sizeof buf - 9)) && n > 0); /* hex: 8 digits */
    fw_puts(label);
    if (base == 16)
        fw_puts("0x");
    fw_puts(buf + n);
}

uint32_t fw_fnv1a(uint32_t hash, const void *data, size_t n)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < n; i++)
        hash = (hash ^ p[i]) * 16777619u;
    return hash;
}
