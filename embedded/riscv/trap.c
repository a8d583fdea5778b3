/* trap.c - what start.S's trap vector reports before the run ends. */
#include <stdint.h>

#include "platform.h"

void fw_trap(uint32_t mcause, uint32_t mepc, uint32_t mtval);

void fw_trap(uint32_t mcause, uint32_t mepc, uint32_t mtval)
{
    /* mcause 0: misaligned fetch, 2: illegal instruction, 4/6: misaligned
     * load/store, 5/7: load/store access fault */
    fw_put_uint("mote-firmware: fault at pc ", mepc, 16);
    fw_put_uint(", mcause ", mcause, 16);
    fw_put_uint(", mtval ", mtval, 16);
    fw_puts("\n");
    fw_exit(1);
}
