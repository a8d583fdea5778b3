/*
 * platform.h - what the firmware example needs from where it runs: a line
 * of text out and a way to stop. Semihosting on the emulated boards
 * (platform_semihost.c), stdio on the host (platform_host.c).
 */
#ifndef MOTE_FIRMWARE_PLATFORM_H
#define MOTE_FIRMWARE_PLATFORM_H

/* Writes a NUL-terminated string. */
void fw_puts(const char *s);
/* Ends the program: status 0 is success. Does not return. */
void fw_exit(int status);
/* Stack high-water mark: fw_stack_paint() fills the unused stack with a
 * pattern, fw_stack_used() says how many bytes were touched since (0 where
 * it is not measured, as on the host). */
void fw_stack_paint(void);
unsigned fw_stack_used(void);

#endif
