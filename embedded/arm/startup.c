/*
 * startup.c - reset and vector table for Cortex-M (ARMv6-M and ARMv7-M):
 * copies .data from flash, clears .bss, turns the FPU on when the build
 * uses it, and runs main(). Faults print a line with the faulting address
 * and exit through semihosting, so an emulated run never hangs.
 */
#include <stdint.h>

#include "platform.h"

int main(void);

extern uint32_t __data_load[], __data_start[], __data_end[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_top[];

void reset_handler(void);
void fault_handler(void);
void fault_report(const uint32_t *frame);

#define SCB_CCR (*(volatile uint32_t *)0xE000ED14u)
#define SCB_CCR_UNALIGN_TRP (1u << 3)
#define SCB_CFSR (*(volatile uint32_t *)0xE000ED28u)
#define SCB_CPACR (*(volatile uint32_t *)0xE000ED88u)

void reset_handler(void)
{
    uint32_t *src = __data_load;
    for (uint32_t *dst = __data_start; dst < __data_end;)
        *dst++ = *src++;
    for (uint32_t *dst = __bss_start; dst < __bss_end;)
        *dst++ = 0;
#if defined(__ARM_ARCH_6M__)
    /* An ARMv6-M core (the M0+) faults on every unaligned access; qemu has
     * no M0+ board and runs this build on a Cortex-M3, which traps them
     * only when asked (on an M0+ the bit reads as one and ignores writes). */
    SCB_CCR |= SCB_CCR_UNALIGN_TRP;
#endif
#if defined(__ARM_FP)
    /* full access to CP10 and CP11 before the first float instruction */
    SCB_CPACR |= 0xFu << 20;
    __asm__ volatile("dsb\n isb" ::: "memory");
#endif
    fw_exit(main());
}

/* The registers the core stacked on entry (r0-r3, r12, lr, pc, xpsr) are
 * at the stack pointer the handler starts with: hand it to fault_report. */
__attribute__((naked)) void fault_handler(void)
{
    __asm__ volatile("mrs r0, msp\n"
                     "bl fault_report\n");
}

void fault_report(const uint32_t *frame)
{
    fw_put_uint("mote-firmware: fault at pc ", frame[6], 16);
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
    /* bit 24: unaligned access, 25: division by zero, 16: undefined instruction */
    fw_put_uint(", CFSR ", SCB_CFSR, 16);
#endif
    fw_puts("\n");
    fw_exit(1);
}

/* Initial stack pointer, then the handlers: reset, NMI, HardFault, and the
 * ARMv7-M MemManage, BusFault, UsageFault (reserved on ARMv6-M). */
typedef struct vector_table {
    uint32_t *stack_top;
    void (*handler[15])(void);
} vector_table;

__attribute__((section(".vectors"), used))
static const vector_table vectors = {
    __stack_top,
    {reset_handler, fault_handler, fault_handler, fault_handler, fault_handler, fault_handler},
};
