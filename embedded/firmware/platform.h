/*
 * platform.h - what the firmware example needs from where it runs: a line
 * of text out, a way to stop, a stack high-water mark and the marks that
 * bound the instructions counted per frame. Semihosting on the emulated
 * boards (platform_semihost.c), stdio on the host (platform_host.c); the
 * numbers and the hash in util.c.
 */
#ifndef MOTE_FIRMWARE_PLATFORM_H
#define MOTE_FIRMWARE_PLATFORM_H

#include <stddef.h>
#include <stdint.h>

/* Writes a NUL-terminated string. */
void fw_puts(const char *s);
/* Writes label, then v in base 10 or 16 (16: "0x" and 8 digits). */
void fw_put_uint(const char *label, uint32_t v, int base);
/* FNV-1a (32-bit) of n bytes, continuing from hash (FW_FNV1A_START for
 * the first bytes): the frame hash that host and targets compare. */
#define FW_FNV1A_START 2166136261u
uint32_t fw_fnv1a(uint32_t hash, const void *data, size_t n);
/* Ends the program: status 0 is success. Does not return. */
void fw_exit(int status);
/* Stack high-water mark: fw_stack_paint() fills the unused stack with a
 * pattern, fw_stack_used() says how many bytes were touched since (0 where
 * it is not measured, as on the host). */
void fw_stack_paint(void);
unsigned fw_stack_used(void);
/* The instructions executed from fw_count_start() to fw_count_stop() are
 * what `make bench-embedded` counts (embedded/qemu/insn_count.c finds the
 * two functions by their addresses); they do nothing themselves. */
void fw_count_start(void);
void fw_count_stop(void);

/* Data that stands for memory outside the chip (the fake LCD's pixels):
 * linked where the board has room, outside the firmware's RAM budget. */
#if defined(__arm__) || defined(__riscv)
#define FW_OFF_CHIP __attribute__((section(".off_chip")))
#else
#define FW_OFF_CHIP
#endif

#endif
