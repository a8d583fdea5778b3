/* fuzz_gltf.c - libFuzzer target: mote_fuzz_gltf (fuzz_entry.c) on each input,
 * .gltf JSON or .glb (or a .glb made of the input: fuzz_entry.h);
 * a broken invariant aborts, so that libFuzzer keeps the input. */
#include "fuzz_entry.h"

#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *err = mote_fuzz_gltf(data, size);
    if (err) {
        fprintf(stderr, "fuzz_gltf: invariant broken: %s\n", err);
        abort();
    }
    return 0;
}
