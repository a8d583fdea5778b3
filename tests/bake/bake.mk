# mote-bake against the loader: tests/bake/test_bake.c includes a header
# that mote-bake writes from tests/data/vertex_colors.babylon and checks it
# against the same file loaded with mote_scene_load, mesh by mesh and
# rendered; run by `make test`.

BAKE_TEST_DIR := $(BUILD)/tests/bake
BAKE_SCENE    := tests/data/vertex_colors.babylon

$(BAKE_TEST_DIR)/baked.h: $(BAKE_SCENE) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_SCENE) -o $@ --name baked --format rgba8888 --size 64x48

# and an orthographic camera's scene, with names of its own
BAKE_ORTHO    := tests/data/ortho_camera.babylon

$(BAKE_TEST_DIR)/ortho.h: $(BAKE_ORTHO) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_ORTHO) -o $@ --name ortho --format rgba8888 --size 64x48

$(BAKE_TEST_DIR)/test_bake: tests/bake/test_bake.c $(BAKE_TEST_DIR)/baked.h $(BAKE_TEST_DIR)/ortho.h \
        $(BUILD)/tests/obj/unity.o $(LIB) | $(DEPS_OK)
	$(CC) $(TEST_CFLAGS) -I$(BAKE_TEST_DIR) -DMOTE_BAKE_SCENE=\"$(CURDIR)/$(BAKE_SCENE)\" \
	    -DMOTE_BAKE_ORTHO=\"$(CURDIR)/$(BAKE_ORTHO)\" $< \
	    $(BUILD)/tests/obj/unity.o $(LIB) $(LDFLAGS) $(LDLIBS) -o $@

test-build: $(BAKE_TEST_DIR)/test_bake
TEST_EXTRA += $(BAKE_TEST_DIR)/test_bake
