/*
 * selftest.c - checks of the harness itself, run by embedded/test-embedded.sh
 * on each emulated board with the instruction counter loaded:
 *   1. between fw_count_start and fw_count_stop, a loop of exactly
 *      SELFTEST_COUNTED instructions (see below), which the counter must
 *      report;
 *   2. a 32-bit load from an odd address, which must fault on the
 *      Cortex-M0+ build (startup.c asks qemu's Cortex-M3 to trap as an M0+
 *      does) and read the right word on the others.
 * Prints "selftest: ..." lines; the fault handler ends a faulting run.
 */
#include <stdint.h>

#include "platform.h"

/* The counted stretch, in assembly so that its length is known: after the
 * call to fw_count_start returns, a load of the loop count (1), LOOPS
 * times a decrement and a branch (2), and the call to fw_count_stop (1).
 * The counter leaves out the two marker functions' own instructions. */
#define LOOPS 200
#define SELFTEST_COUNTED (1 + 2 * LOOPS + 1)
#define STR(x) #x
#define XSTR(x) STR(x)

static void counted_loop(void)
{
#if defined(__arm__)
    /* GCC hands Thumb-1 inline assembly to the assembler in the old
     * divided syntax */
    __asm__ volatile(".syntax unified\n"
                     "bl fw_count_start\n"
                     "movs r0, #" XSTR(LOOPS) "\n"
                     "1: subs r0, r0, #1\n"
                     "bne 1b\n"
                     "bl fw_count_stop\n"
                     ::: "r0", "r1", "r2", "r3", "r12", "lr", "cc", "memory");
#elif defined(__riscv)
    __asm__ volatile("jal ra, fw_count_start\n"
                     "li t0, " XSTR(LOOPS) "\n"
                     "1: addi t0, t0, -1\n"
                     "bnez t0, 1b\n"
                     "jal ra, fw_count_stop\n"
                     ::: "ra", "t0", "t1", "t2", "t3", "t4", "t5", "t6",
                         "a0", "a1", "a2", "a3", "a4", "a5", "a6", "a7", "memory");
#else
#error "selftest: ARM or RISC-V only"
#endif
}

int main(void)
{
    counted_loop();
    fw_put_uint("selftest: counted stretch of ", SELFTEST_COUNTED, 10);
    fw_puts(" instructions\n");

    static uint8_t bytes[8] __attribute__((aligned(4))) = {0x10, 0x21, 0x32, 0x43, 0x54, 0x65, 0x76, 0x87};
    /* hidden from the compiler, which would otherwise load a pointer it
     * knows to be odd byte by byte */
    uintptr_t address = (uintptr_t)bytes;
    __asm__("" : "+r"(address));
    volatile uint32_t *odd = (volatile uint32_t *)(address + 1);
    fw_puts("selftest: loading a word from an odd address\n");
    uint32_t v = *odd;
    fw_put_uint("selftest: unaligned load read ", v, 16);
    fw_puts(v == 0x54433221u ? ", right\n" : ", wrong\n");
    return v == 0x54433221u ? 0 : 1;
}
