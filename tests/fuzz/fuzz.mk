# Fuzzing (libFuzzer, clang) and memcheck (valgrind).
#
#   make fuzz                 each target for FUZZ_SECONDS (60) s, prints executions
#   make fuzz FUZZ_TARGETS=draw FUZZ_SECONDS=600
#   make fuzz-build           only build the targets
#   make valgrind             the examples and mote-render under valgrind memcheck
#
# The targets and the corpus replay in `make test` (tests/test_fuzz_regressions.c)
# share tests/fuzz/fuzz_entry.c. Crashes are written to $(FUZZ_BUILD)/crashes/;
# keep each one, once fixed, in tests/fuzz/regressions/<target>/.

FUZZ_CC      ?= clang
FUZZ_BUILD   ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= draw texture scene gltf folder
FUZZ_DIR     := $(FUZZ_BUILD)/clang
FUZZ_OK      := $(FUZZ_DIR)/.fuzz-ok
# No OpenMP here: clang's runtime is another package, and tiles run through
# the fuzzer's own parallel_for anyway.
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
# MOTE_PIECE_MIN=2: the fuzzer's draws (up to 48 triangles) are cut into
# pieces set up apart, as big meshes are (bin.c).
FUZZ_CFLAGS   = -std=c99 -O1 -g -ffp-contract=off $(WARN) -Iinclude -Isrc -Itests \
                -DMOTE_PIECE_MIN=2 $(PKG_CFLAGS) $(FUZZ_SAN) $(FUZZ_EXTRA)
FUZZ_LIB_OBJ := $(patsubst src/%.c,$(FUZZ_DIR)/obj/%.o,$(CORE_SRC) $(IO_SRC))
FUZZ_BINS    := $(patsubst %,$(FUZZ_DIR)/fuzz_%,$(FUZZ_TARGETS))

.PHONY: fuzz fuzz-build valgrind valgrind-deps
.PRECIOUS: $(FUZZ_DIR)/obj/%.o $(FUZZ_DIR)/obj/fuzz/%.o

fuzz: fuzz-build
	@FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_BUILD=$(FUZZ_BUILD) \
	    sh tests/fuzz/run.sh $(FUZZ_DIR) $(FUZZ_TARGETS)

fuzz-build: $(FUZZ_BINS)

# clang with the libFuzzer runtime; installed (Debian) when missing.
$(FUZZ_OK): | $(DEPS_OK)
	@mkdir -p $(dir $@)
	@printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n);\nint LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { (void)d; (void)n; return 0; }\n' > $(FUZZ_DIR)/probe.c
	@$(FUZZ_CC) -fsanitize=fuzzer $(FUZZ_DIR)/probe.c -o $(FUZZ_DIR)/probe 2>/dev/null || \
	    MOTE_EXTRA_PACKAGES="clang libclang-rt-14-dev" sh third_party/setup.sh
	@$(FUZZ_CC) -fsanitize=fuzzer $(FUZZ_DIR)/probe.c -o $(FUZZ_DIR)/probe || \
	    { echo "error: $(FUZZ_CC) cannot link libFuzzer (-fsanitize=fuzzer)" >&2; exit 1; }
	@touch $@

$(FUZZ_DIR)/obj/%.o: src/%.c $(wildcard include/mote/*.h src/core/*.h src/io/*.h) | $(FUZZ_OK)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link -c $< -o $@

$(FUZZ_DIR)/obj/fuzz/%.o: tests/fuzz/%.c tests/fuzz/fuzz_entry.h $(wildcard include/mote/*.h src/core/*.h src/io/*.h) | $(FUZZ_OK)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link -c $< -o $@

$(FUZZ_DIR)/fuzz_%: $(FUZZ_DIR)/obj/fuzz/fuzz_%.o $(FUZZ_DIR)/obj/fuzz/fuzz_entry.o $(FUZZ_LIB_OBJ)
	$(FUZZ_CC) -fsanitize=fuzzer $(FUZZ_SAN) $^ $(PKG_LIBS) -lm -o $@

# The corpus replay includes fuzz_entry.c: rebuild it when that changes.
$(BUILD)/tests/obj/test_fuzz_regressions.o: tests/fuzz/fuzz_entry.c tests/fuzz/fuzz_entry.h

# valgrind is installed (Debian) when missing: without it every case is
# ignored and the run says nothing.
valgrind: lib examples valgrind-deps
	@BIN=$(BIN) sh tests/valgrind.sh

valgrind-deps: | $(DEPS_OK)
	@MOTE_EXTRA_PACKAGES=valgrind sh third_party/setup.sh

# `make test VALGRIND=1` adds the memcheck runs to the suite (about a
# minute and a half on two cores).
ifeq ($(VALGRIND),1)
TEST_EXTRA += tests/valgrind.sh
test: examples valgrind-deps
test: export BIN := $(BIN)
endif
