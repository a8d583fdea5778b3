/*
 * startup.c - reset and vector table for Cortex-M (ARMv6-M and ARMv7-M):
 * copies .data from flash, clears .bss, turns the FPU on when the build
 * uses it, and runs main(). Faults print a line and exit through
 * semihosting, so an emulated run never hangs.
 */
#include <stdint.h>

#include "platform.h"

int main(void);

extern uint32_t __data_load[], __data_start[], __data_end[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_top[];

void reset_handler(void);
void fault_handler(void);

void reset_handler(void)
{
    uint32_t *src = __data_load;
    for (uint32_t *dst = __data_start; dst < __data_end;)
        *dst++ = *src++;
    for (uint32_t *dst = __bss_start; dst < __bss_end;)
        *dst++ = 0;
#if defined(__ARM_FP)
    /* CPACR: full access to CP10 and CP11 before the first float instruction */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n isb" ::: "memory");
#endif
    fw_exit(main());
}

void fault_handler(void)
{
    fw_puts("mote-firmware: fault\n");
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
