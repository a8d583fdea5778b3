/*
 * platform_semihost.c - output and exit through semihosting: the debugger
 * (here qemu, -semihosting-config enable=on,target=native) services
 * SYS_WRITE0 and SYS_EXIT, so the example needs no UART driver.
 * ARM: operation in r0, argument in r1, "bkpt 0xab" (Thumb).
 * RISC-V: operation in a0, argument in a1, the uncompressed
 * "slli x0, x0, 0x1f; ebreak; srai x0, x0, 7" sequence.
 */
#include "platform.h"

#include <stdint.h>

#define SYS_WRITE0 0x04
#define SYS_EXIT 0x18
#define ADP_STOPPED_APPLICATION_EXIT 0x20026
#define ADP_STOPPED_RUN_TIME_ERROR 0x20023

static uintptr_t semihost(uintptr_t op, uintptr_t arg)
{
#if defined(__arm__)
    register uintptr_t r0 __asm__("r0") = op;
    register uintptr_t r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
#elif defined(__riscv)
    register uintptr_t a0 __asm__("a0") = op;
    register uintptr_t a1 __asm__("a1") = arg;
    __asm__ volatile(".option push\n"
                     ".option norvc\n"
                     ".balign 16\n"
                     "slli x0, x0, 0x1f\n"
                     "ebreak\n"
                     "srai x0, x0, 7\n"
                     ".option pop\n"
                     : "+r"(a0) : "r"(a1) : "memory");
    return a0;
#else
#error "semihosting: ARM or RISC-V only"
#endif
}

void fw_puts(const char *s)
{
    semihost(SYS_WRITE0, (uintptr_t)s);
}

void fw_exit(int status)
{
    /* on 32-bit targets the reason code is the argument itself */
    semihost(SYS_EXIT, status == 0 ? ADP_STOPPED_APPLICATION_EXIT : ADP_STOPPED_RUN_TIME_ERROR);
    for (;;) {
    }
}

#define STACK_PAINT 0x5eed5eedu

extern uint32_t __stack_bottom[], __stack_top[];

/* noinline: its own frame stays above the painted area */
__attribute__((noinline)) void fw_stack_paint(void)
{
    volatile uint32_t here = 0;
    uintptr_t limit = (uintptr_t)&here - 64;
    for (volatile uint32_t *p = __stack_bottom; (uintptr_t)p < limit; p++)
        *p = STACK_PAINT;
}

unsigned fw_stack_used(void)
{
    const uint32_t *p = __stack_bottom;
    while (p < __stack_top && *p == STACK_PAINT)
        p++;
    return (unsigned)((const char *)__stack_top - (const char *)p);
}

/* noipa: never inlined, cloned or folded into one another (identical
 * bodies would be), so that each keeps an address of its own */
__attribute__((noipa)) void fw_count_start(void)
{
    __asm__ volatile("" ::: "memory");
}

__attribute__((noipa)) void fw_count_stop(void)
{
    __asm__ volatile("" ::: "memory");
}
