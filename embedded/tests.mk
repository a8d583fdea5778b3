# Host tests of embedded/ code, run by `make test` (embedded/tests/):
#   test_bake_texture_size  mote-bake --texture-size, which the firmware's
#                           Suzanne needs, against the loaded texture

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

test-build: $(BAKE_SIZE_TEST)
TEST_EXTRA += $(BAKE_SIZE_TEST)
