/* fuzz_draw.c - libFuzzer target: mote_fuzz_draw (fuzz_entry.c) on each input;
 * a broken invariant aborts, so that libFuzzer keeps the input. */
#include "fuzz_entry.h"

#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *err = mote_fuzz_draw(data, size);
    if (err) {
        fprintf(stderr, "fuzz_draw: invariant broken: %s\n", err);
        abort();
    }
    return 0;
}
