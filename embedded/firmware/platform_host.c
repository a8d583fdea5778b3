/* platform_host.c - the firmware example on the host, for the reference hash. */
#include "platform.h"

#include <stdio.h>
#include <stdlib.h>

void fw_puts(const char *s)
{
    fputs(s, stdout);
    fflush(stdout);
}

void fw_exit(int status)
{
    exit(status);
}

void fw_stack_paint(void)
{
}

unsigned fw_stack_used(void)
{
    return 0;
}

void fw_count_start(void)
{
}

void fw_count_stop(void)
{
}
