/*
 * insn_count.c - a QEMU TCG plugin that counts the guest instructions a
 * firmware executes between two marker functions, for `make
 * bench-embedded`.
 *
 *   qemu-system-arm ... -plugin libinsn_count.so,start=0xADDR,stop=0xADDR
 *
 * start and stop are the addresses of two empty, never-inlined functions
 * of the firmware (fw_count_start and fw_count_stop in
 * embedded/firmware/platform_semihost.c, read from the ELF with nm). The
 * firmware calls start before the work it wants counted and stop after
 * it, as often as it likes (it stops around its flush callback, which
 * stands for the display). At exit the plugin prints one line:
 *
 *   insn_count: counted N instructions in K intervals, T in all
 *
 * How: every translated block adds its instruction count to one total
 * when it executes (an inline add, no call: qemu runs at nearly full
 * speed); a block that starts at a marker also calls back into the
 * plugin, which notes the total there. The counted figure is the sum of
 * (total at stop - total at start): every instruction from the return of
 * fw_count_start to the call of fw_count_stop, the markers' own left out
 * (embedded/tests/selftest.c checks this exactly). A function's entry
 * always starts a block (it is only ever reached by a call), so no marker
 * is missed, and nothing in the firmware changes but two calls. Markers are function
 * addresses rather than a guest-visible counter or a magic instruction:
 * they need no cooperation from the board (semihosting and MMIO differ
 * between the targets) and work the same on ARM and RISC-V.
 *
 * A block counts all its instructions when it starts, so a fault in the
 * middle of one overcounts by the rest of that block; one vCPU only (the
 * firmware runs on one).
 *
 * With profile=FILE it also counts each translated block's instructions
 * over the whole run (markers or not) and writes "ADDRESS COUNT" lines to
 * FILE at exit, which embedded/profile.sh sums by function.
 *
 * Debian ships no qemu-plugin.h: the few declarations used are below, as
 * QEMU's plugin API version 1 (qemu 7.2) defines them.
 */
#include <inttypes.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the part of QEMU's plugin API this plugin uses -------------------- */

#define QEMU_PLUGIN_EXPORT __attribute__((visibility("default")))

typedef uint64_t qemu_plugin_id_t;
typedef struct qemu_info_t qemu_info_t; /* only passed through */
struct qemu_plugin_tb;

enum qemu_plugin_cb_flags { QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_CB_R_REGS, QEMU_PLUGIN_CB_RW_REGS };
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };

typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void *userdata);
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_cb(struct qemu_plugin_tb *tb, qemu_plugin_vcpu_udata_cb_t cb,
                                          enum qemu_plugin_cb_flags flags, void *userdata);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
                                              void *ptr, uint64_t imm);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
uint64_t qemu_plugin_tb_vaddr(const struct qemu_plugin_tb *tb);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void *userdata);
void qemu_plugin_outs(const char *string);

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc,
                                           char **argv);

/* The API version this plugin was written against. */
QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;

/* ---- counting ---------------------------------------------------------- */

static uint64_t start_addr, stop_addr;
static uint64_t total;          /* every instruction executed */
static uint64_t counted;        /* those between start and stop */
static uint64_t started_at;     /* total when counting last started */
static bool counting;
static uint64_t intervals;

/* userdata: the marker block's instruction count. QEMU runs a block's
 * callbacks before its inline adds, so the total here has not counted
 * the marker yet: leave it out, as on_stop leaves out its own. */
static void on_start(unsigned int vcpu_index, void *userdata)
{
    (void)vcpu_index;
    if (!counting) {
        counting = true;
        started_at = total + (uint64_t)(uintptr_t)userdata;
        intervals++;
    }
}

static void on_stop(unsigned int vcpu_index, void *userdata)
{
    (void)vcpu_index;
    (void)userdata;
    if (counting) {
        counting = false;
        counted += total - started_at;
    }
}

/* profile=FILE: instructions executed by blocks starting at each address,
 * in an open-addressed table (a block translated again keeps its entry) */
#define PROFILE_SLOTS (1u << 16)
typedef struct profile_slot { uint64_t pc, insns; } profile_slot;
static profile_slot *profile;
static const char *profile_path;
static bool profile_full;

static uint64_t *profile_counter(uint64_t pc)
{
    uint32_t h = (uint32_t)((pc * 0x9e3779b97f4a7c15u) >> 48) & (PROFILE_SLOTS - 1);
    for (uint32_t i = 0; i < PROFILE_SLOTS; i++, h = (h + 1) & (PROFILE_SLOTS - 1)) {
        profile_slot *s = &profile[h];
        if (s->pc == pc + 1 || s->pc == 0) {
            s->pc = pc + 1;       /* 0 marks a free slot: address 0 is stored as 1 */
            return &s->insns;
        }
    }
    profile_full = true;
    return NULL;
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    uint64_t pc = qemu_plugin_tb_vaddr(tb);
    size_t n = qemu_plugin_tb_n_insns(tb);
    uint64_t *slot = profile ? profile_counter(pc) : NULL;
    if (slot)
        qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, slot, n);
    if (pc == start_addr)
        qemu_plugin_register_vcpu_tb_exec_cb(tb, on_start, QEMU_PLUGIN_CB_NO_REGS, (void *)(uintptr_t)n);
    else if (pc == stop_addr)
        qemu_plugin_register_vcpu_tb_exec_cb(tb, on_stop, QEMU_PLUGIN_CB_NO_REGS, NULL);
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &total, n);
}

static void on_exit(qemu_plugin_id_t id, void *userdata)
{
    (void)id;
    (void)userdata;
    char line[160];
    if (counting)
        snprintf(line, sizeof line, "insn_count: the firmware never called the stop marker after "
                                    "its last start (%" PRIu64 " in all)\n", total);
    else
        snprintf(line, sizeof line, "insn_count: counted %" PRIu64 " instructions in %" PRIu64
                                    " intervals, %" PRIu64 " in all\n", counted, intervals, total);
    qemu_plugin_outs(line);
    if (!profile)
        return;
    FILE *f = fopen(profile_path, "w");
    if (!f || profile_full) {
        qemu_plugin_outs(f ? "insn_count: the profile table overflowed\n" : "insn_count: cannot write the profile\n");
        if (f)
            fclose(f);
        return;
    }
    for (uint32_t i = 0; i < PROFILE_SLOTS; i++)
        if (profile[i].pc)
            fprintf(f, "%" PRIx64 " %" PRIu64 "\n", profile[i].pc - 1, profile[i].insns);
    fclose(f);
}

/* "name=0x..." to an address; false when the argument is not that one. */
static bool parse_addr(const char *arg, const char *name, uint64_t *out)
{
    size_t n = strlen(name);
    if (strncmp(arg, name, n) != 0 || arg[n] != '=')
        return false;
    char *end;
    *out = strtoull(arg + n + 1, &end, 0);
    /* Thumb function symbols carry the mode in bit 0; blocks start at the
     * even address */
    *out &= ~(uint64_t)1;
    return *end == '\0' && end != arg + n + 1;
}

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc,
                                           char **argv)
{
    (void)info;
    bool have_start = false, have_stop = false;
    for (int i = 0; i < argc; i++) {
        if (parse_addr(argv[i], "start", &start_addr))
            have_start = true;
        else if (parse_addr(argv[i], "stop", &stop_addr))
            have_stop = true;
        else if (strncmp(argv[i], "profile=", 8) == 0 && argv[i][8])
            profile_path = argv[i] + 8;
        else {
            fprintf(stderr, "insn_count: unknown argument '%s' (start=ADDR,stop=ADDR[,profile=FILE])\n", argv[i]);
            return -1;
        }
    }
    if (!have_start || !have_stop || start_addr == stop_addr) {
        fprintf(stderr, "insn_count: needs start=ADDR,stop=ADDR, two different addresses\n");
        return -1;
    }
    if (profile_path && !(profile = calloc(PROFILE_SLOTS, sizeof *profile))) {
        fprintf(stderr, "insn_count: no memory for the profile\n");
        return -1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit, NULL);
    return 0;
}
