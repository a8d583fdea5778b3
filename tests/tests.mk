# Unity test suite: one executable per tests/test_*.c, linked with the
# shared helpers in tests/support/ and the reference renderer in tests/ref/.
# tests/run.sh runs them all and ends with "N passed, M failed".

UNITY_DIR_LOCAL := third_party/unity
UNITY_OK     := $(UNITY_DIR_LOCAL)/src/unity.c
TEST_SRC     := $(sort $(wildcard tests/test_*.c))
TEST_BIN     := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
TEST_SUPPORT := $(sort $(wildcard tests/support/*.c tests/ref/*.c))
TEST_SUP_OBJ := $(patsubst tests/%.c,$(BUILD)/tests/obj/%.o,$(TEST_SUPPORT))
TEST_CFLAGS   = $(CFLAGS) -I$(UNITY_DIR_LOCAL)/src -Itests \
                -DMOTE_SOURCE_DIR=\"$(CURDIR)\"
# Extra checks that print a Unity-style summary; other .mk files append.
TEST_EXTRA   ?=

.PHONY: test test-build
test: test-build
	@sh tests/run.sh $(TEST_BIN) $(TEST_EXTRA)

test-build: $(TEST_BIN)

$(UNITY_OK):
	@sh third_party/get-unity.sh $(UNITY_DIR_LOCAL)

$(BUILD)/tests/obj/unity.o: $(UNITY_OK) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) -std=c99 -O2 -g $(SANFLAGS) -c $< -o $@

$(BUILD)/tests/obj/%.o: tests/%.c $(wildcard tests/*.h tests/*/*.h include/mote/*.h src/core/*.h src/io/*.h) $(UNITY_OK) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) -c $< -o $@

$(BUILD)/tests/test_%: $(BUILD)/tests/obj/test_%.o $(TEST_SUP_OBJ) $(BUILD)/tests/obj/unity.o $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

# test_setup_portable compiles src/core/setup.c a second time (without __int128)
$(BUILD)/tests/obj/test_setup_portable.o: src/core/setup.c
# test_edge32 compiles src/core/raster.c a second time (its 32-bit first row)
$(BUILD)/tests/obj/test_edge32.o: src/core/raster.c
# test_vertex compiles src/core/vertex.c a second time (its static conversions and lighting)
$(BUILD)/tests/obj/test_vertex.o: src/core/vertex.c

# The glTF scenes tests/test_gltf.c reads, written by tools/gen_gltf.c.
GLTF_TEST_DIR := $(BUILD)/gltf
$(GLTF_TEST_DIR)/.ok: $(BIN)/gen_gltf
	@mkdir -p $(GLTF_TEST_DIR)
	$(BIN)/gen_gltf $(GLTF_TEST_DIR)
	@touch $@
$(BUILD)/tests/obj/test_gltf.o: TEST_CFLAGS += -DMOTE_GLTF_DIR=\"$(CURDIR)/$(GLTF_TEST_DIR)\"
$(BUILD)/tests/test_gltf: | $(GLTF_TEST_DIR)/.ok

# tests/test_gltf_errors.c runs every glTF file of Debian's
# assimp-testmodels: installed when missing (as root); where it cannot
# be, that test is skipped, saying so.
.PHONY: gltf-corpus-deps
gltf-corpus-deps: | $(DEPS_OK)
	@MOTE_EXTRA_PACKAGES=assimp-testmodels sh third_party/setup.sh || \
	    echo "note: assimp-testmodels is not installed; its glTF test is skipped"
test: gltf-corpus-deps
