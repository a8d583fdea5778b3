/* fuzz_folder.c - libFuzzer target: mote_fuzz_folder (fuzz_entry.c) on each input;
 * a broken invariant aborts, so that libFuzzer keeps the input. */
#include "fuzz_entry.h"

#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *err = mote_fuzz_folder(data, size);
    if (err) {
        fprintf(stderr, "fuzz_folder: invariant broken: %s\n", err);
        abort();
    }
    return 0;
}
