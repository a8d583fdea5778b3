# The integer vertex stage (MOTE_FIXED_VERTEX=1, what a core without an FPU
# builds by default) on the host, with the firmware's pixel loop: the library built again with it, and the
# suites that hold the vertex stage to the reference, the pixel rules and
# band rendering, run by `make test` against that library. The firmware's
# frame hash on the emulated Cortex-M0+ and RV32IMAC is compared with the
# same configuration built for the host (embedded/cross.mk).

FIXED_DIR   := $(BUILD)/fixed
# The firmware's pixel loop too (MOTE_FIRMWARE_SPANS, span_fw.c; a size
# build's default), and no specialised loops, as in a size build:
# test_spans holds it to the generic loop.
FIXED_FLAG  := -DMOTE_FIXED_VERTEX=1 -DMOTE_FIRMWARE_SPANS=1 -DMOTE_SPECIALISE_SPANS=0
FIXED_OBJ   := $(patsubst src/%.c,$(FIXED_DIR)/obj/%.o,$(CORE_SRC) $(IO_SRC))
FIXED_LIB   := $(FIXED_DIR)/libmote.a
FIXED_TESTS := core accuracy raster_rules clip stability formats_bands compact spans
FIXED_BIN   := $(foreach t,$(FIXED_TESTS),$(FIXED_DIR)/test_$(t))
FIXED_SUP   := $(patsubst tests/%.c,$(FIXED_DIR)/obj/tests/%.o,$(sort $(wildcard tests/support/*.c tests/ref/*.c)))

$(FIXED_DIR)/obj/core/%.o: CFLAGS += $(CORE_OPT)
$(FIXED_DIR)/obj/%.o: src/%.c $(wildcard include/mote/*.h src/core/*.h src/io/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(FIXED_FLAG) -c $< -o $@

$(FIXED_LIB): $(FIXED_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(FIXED_DIR)/obj/tests/%.o: tests/%.c $(wildcard tests/*.h tests/*/*.h include/mote/*.h) third_party/unity/src/unity.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) $(FIXED_FLAG) -c $< -o $@

$(FIXED_DIR)/test_%: $(FIXED_DIR)/obj/tests/test_%.o $(FIXED_SUP) $(BUILD)/tests/obj/unity.o $(FIXED_LIB)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

test-build: $(FIXED_BIN)
TEST_EXTRA += $(FIXED_BIN)
