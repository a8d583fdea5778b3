# Host tests of embedded/ code, run by `make test` (embedded/tests/):
#   test_mini_libc          the firmware's word-wise memcpy and memset
#                           against the C library's (its functions renamed
#                           so as not to replace the host's own)
#   test_bake_texture_size  mote-bake --texture-size, which the firmware's
#                           Suzanne needs, against the loaded texture

MINI_LIBC_TEST := $(BUILD)/tests/test_mini_libc
$(MINI_LIBC_TEST): embedded/tests/test_mini_libc.c embedded/firmware/mini_libc.c embedded/include/string.h \
        $(BUILD)/tests/obj/unity.o | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) -std=c99 -O2 -g $(WARN) $(SANFLAGS) -ffreestanding -fno-builtin $(MINI_LIBC_FLAGS) -Iembedded/include \
	    -Dmemcpy=mini_memcpy -Dmemmove=mini_memmove -Dmemset=mini_memset -Dmemcmp=mini_memcmp \
	    -c embedded/firmware/mini_libc.c -o $(BUILD)/tests/obj/mini_libc.o
	$(CC) -std=c99 -O2 -g $(WARN) $(SANFLAGS) -I$(UNITY_DIR_LOCAL)/src embedded/tests/test_mini_libc.c \
	    $(BUILD)/tests/obj/mini_libc.o $(BUILD)/tests/obj/unity.o -o $@

BAKE_SIZE_DIR  := $(BUILD)/tests/bake-texture-size
BAKE_SIZE_CUBE := embedded/scene/cube.babylon
BAKE_SIZE_TEST := $(BUILD)/tests/test_bake_texture_size

$(BAKE_SIZE_DIR)/quarter.h: $(BAKE_SIZE_CUBE) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $< -o $@ --name quarter --format rgba8888 --texture-size 16x16

$(BAKE_SIZE_DIR)/wide.h: $(BAKE_SIZE_CUBE) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $< -o $@ --name wide --format rgba8888 --texture-size 128x16

$(BAKE_SIZE_TEST): embedded/tests/test_bake_texture_size.c $(BAKE_SIZE_DIR)/quarter.h $(BAKE_SIZE_DIR)/wide.h \
        $(BUILD)/tests/obj/unity.o $(LIB) | $(DEPS_OK)
	$(CC) $(TEST_CFLAGS) -I$(BAKE_SIZE_DIR) -DMOTE_BAKE_CUBE=\"$(CURDIR)/$(BAKE_SIZE_CUBE)\" $< \
	    $(BUILD)/tests/obj/unity.o $(LIB) $(LDFLAGS) $(LDLIBS) -o $@

test-build: $(MINI_LIBC_TEST) $(BAKE_SIZE_TEST)
TEST_EXTRA += $(MINI_LIBC_TEST) $(BAKE_SIZE_TEST)
