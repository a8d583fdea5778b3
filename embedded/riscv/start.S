/*
 * start.S - reset code for RV32 (machine mode, no OS): stack and global
 * pointer, a trap vector that reports and exits, .data copied from flash,
 * .bss cleared, then main() and exit.
 */
    /* the CSR instructions, part of every RV32 core, are an extension of
     * their own to the assembler */
    .option arch, +zicsr
    .section .text.start, "ax"
    .globl _start
_start:
    .option push
    .option norelax
    la gp, __global_pointer$
    .option pop
    la sp, __stack_top
    la t0, trap_entry
    csrw mtvec, t0
    la t0, __data_load
    la t1, __data_start
    la t2, __data_end
1:  bgeu t1, t2, 2f
    lw t3, 0(t0)
    sw t3, 0(t1)
    addi t0, t0, 4
    addi t1, t1, 4
    j 1b
2:  la t1, __bss_start
    la t2, __bss_end
3:  bgeu t1, t2, 4f
    sw zero, 0(t1)
    addi t1, t1, 4
    j 3b
4:  call main
    call fw_exit
5:  j 5b

/* Any trap (the firmware enables no interrupt) is a fault: report the
 * cause and address, fw_trap(mcause, mepc, mtval), which exits. mtvec's
 * direct mode needs a 4-byte aligned entry. */
    .balign 4
trap_entry:
    csrr a0, mcause
    csrr a1, mepc
    csrr a2, mtval
    call fw_trap
6:  j 6b
