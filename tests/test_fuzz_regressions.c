/*
 * test_fuzz_regressions.c - replays every input kept in
 * tests/fuzz/regressions/<target>/ (crashes the fuzzers found, now fixed)
 * and tests/fuzz/seeds/<target>/ through the same entry functions as the
 * libFuzzer targets, so that `make test` (and `make test SAN=1`) keeps them
 * fixed without clang or libFuzzer.
 */
#include "fuzz/fuzz_entry.c"   /* first: it asks for POSIX before any system header */

#include "unity.h"

#include <dirent.h>
#include <sys/stat.h>

typedef const char *(*entry_fn)(const uint8_t *data, size_t size);

void setUp(void) {}
void tearDown(void) {}

static uint8_t *read_all(const char *path, size_t *size)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    uint8_t *data = NULL;
    size_t cap = 0, n = 0;
    for (;;) {
        if (n == cap) {
            cap = cap ? cap * 2 : 4096;
            uint8_t *grown = (uint8_t *)realloc(data, cap);
            if (!grown) {
                free(data);
                fclose(fp);
                return NULL;
            }
            data = grown;
        }
        size_t got = fread(data + n, 1, cap - n, fp);
        if (got == 0)
            break;
        n += got;
    }
    fclose(fp);
    *size = n;
    return data;
}

/* Runs fn on every regular file of MOTE_SOURCE_DIR/dir, appending
 * "file: broken invariant" lines to failures. Returns how many inputs ran. */
static int replay_dir(const char *dir, entry_fn fn, char *failures, size_t cap)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", MOTE_SOURCE_DIR, dir);
    DIR *d = opendir(path);
    if (!d)
        return 0;
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        char file[1400];
        struct stat st;
        snprintf(file, sizeof file, "%s/%s", path, e->d_name);
        if (stat(file, &st) != 0 || !S_ISREG(st.st_mode))
            continue;
        size_t size = 0;
        uint8_t *data = read_all(file, &size);
        TEST_ASSERT_NOT_NULL_MESSAGE(data, file);
        const char *err = fn(data, size);
        free(data);
        if (err) {
            size_t used = strlen(failures);
            snprintf(failures + used, cap - used, "%s%s/%s: %s", used ? "; " : "", dir,
                     e->d_name, err);
        }
        count++;
    }
    closedir(d);
    return count;
}

static void replay_target(const char *target, entry_fn fn)
{
    char dir[128], failures[2048] = "";
    snprintf(dir, sizeof dir, "tests/fuzz/seeds/%s", target);
    int seeds = replay_dir(dir, fn, failures, sizeof failures);
    snprintf(dir, sizeof dir, "tests/fuzz/regressions/%s", target);
    replay_dir(dir, fn, failures, sizeof failures);
    if (failures[0])
        TEST_FAIL_MESSAGE(failures);
    TEST_ASSERT_GREATER_THAN_MESSAGE(0, seeds, "no seed inputs found: tests/fuzz/seeds missing?");
}

static void draw_path_should_hold_its_invariants_on_every_kept_input(void)
{
    replay_target("draw", mote_fuzz_draw);
}

static void texture_loader_should_hold_its_invariants_on_every_kept_input(void)
{
    replay_target("texture", mote_fuzz_texture);
}

static void scene_loader_should_hold_its_invariants_on_every_kept_input(void)
{
    replay_target("scene", mote_fuzz_scene);
}

static void gltf_loader_should_hold_its_invariants_on_every_kept_input(void)
{
    replay_target("gltf", mote_fuzz_gltf);
}

static void folder_resolution_should_hold_its_invariants_on_every_kept_input(void)
{
    replay_target("folder", mote_fuzz_folder);
}

static void every_entry_should_survive_empty_and_all_ones_inputs(void)
{
    static uint8_t ones[4096];
    memset(ones, 0xff, sizeof ones);
    TEST_ASSERT_NULL(mote_fuzz_draw(NULL, 0));
    TEST_ASSERT_NULL(mote_fuzz_texture(NULL, 0));
    TEST_ASSERT_NULL(mote_fuzz_scene(NULL, 0));
    TEST_ASSERT_NULL(mote_fuzz_folder(NULL, 0));
    TEST_ASSERT_NULL(mote_fuzz_gltf(NULL, 0));
    TEST_ASSERT_NULL(mote_fuzz_draw(ones, sizeof ones));
    TEST_ASSERT_NULL(mote_fuzz_texture(ones, sizeof ones));
    TEST_ASSERT_NULL(mote_fuzz_scene(ones, sizeof ones));
    TEST_ASSERT_NULL(mote_fuzz_folder(ones, sizeof ones));
    TEST_ASSERT_NULL(mote_fuzz_gltf(ones, sizeof ones));
}

/* The canaries are what catch stray writes without sanitizers: make sure
 * they would. */
static void canary_check_should_notice_a_write_just_past_or_before_a_buffer(void)
{
    fz_buf b;
    TEST_ASSERT_TRUE(fz_buf_alloc(&b, 100));
    TEST_ASSERT_TRUE(fz_buf_intact(&b));
    memset(b.p, 0, b.size);
    TEST_ASSERT_TRUE(fz_buf_intact(&b));
    b.p[b.size] ^= 1;
    TEST_ASSERT_FALSE(fz_buf_intact(&b));
    b.p[b.size] ^= 1;
    b.p[-1] ^= 0x80;
    TEST_ASSERT_FALSE(fz_buf_intact(&b));
    fz_buf_free(&b);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(draw_path_should_hold_its_invariants_on_every_kept_input);
    RUN_TEST(texture_loader_should_hold_its_invariants_on_every_kept_input);
    RUN_TEST(scene_loader_should_hold_its_invariants_on_every_kept_input);
    RUN_TEST(gltf_loader_should_hold_its_invariants_on_every_kept_input);
    RUN_TEST(folder_resolution_should_hold_its_invariants_on_every_kept_input);
    RUN_TEST(every_entry_should_survive_empty_and_all_ones_inputs);
    RUN_TEST(canary_check_should_notice_a_write_just_past_or_before_a_buffer);
    return UNITY_END();
}
