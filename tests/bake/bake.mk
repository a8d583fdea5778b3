# mote-bake against the loader: tests/bake/test_bake.c includes the headers
# that mote-bake writes from tests/data/vertex_colors.babylon (--keep-order:
# its arrays are compared with the loaded ones byte for byte),
# tests/data/bake_hidden.babylon and tests/data/ortho_camera.babylon (an
# orthographic camera), from assets/cube.babylon (textured) in each
# texture format and from gen_gltf's lines.gltf (points and lines), and
# checks them against the same files loaded with mote_scene_load, mesh by
# mesh and rendered; the cube baked with --compact; and
# tests/data/transparency.babylon and fog.babylon with their draw options
# and order; and, in the vertex cache's order, assets/torus.babylon and
# tests/bake/reorder.babylon (written by tests/bake/make_reorder.py:
# shuffled grids, an instance, sub-meshes), as floats and --compact; run by
# `make test`.

BAKE_TEST_DIR := $(BUILD)/tests/bake
BAKE_SCENE    := tests/data/vertex_colors.babylon
BAKE_HIDDEN   := tests/data/bake_hidden.babylon
BAKE_ORTHO    := tests/data/ortho_camera.babylon
BAKE_CUBE     := assets/cube.babylon
BAKE_FORMATS  := rgb565 rgba8888 grey8
BAKE_CUBES    := $(patsubst %,$(BAKE_TEST_DIR)/cube_%.h,$(BAKE_FORMATS))

$(BAKE_TEST_DIR)/baked.h: $(BAKE_SCENE) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_SCENE) -o $@ --name baked --format rgba8888 --size 64x48 --keep-order

$(BAKE_TEST_DIR)/ortho.h: $(BAKE_ORTHO) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_ORTHO) -o $@ --name ortho --format rgba8888 --size 64x48

$(BAKE_TEST_DIR)/baked_hidden.h: $(BAKE_HIDDEN) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_HIDDEN) -o $@ --name baked_hidden --format rgba8888 --size 64x48

$(BAKE_TEST_DIR)/cube_%.h: $(BAKE_CUBE) assets/checker.png $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_CUBE) -o $@ --name cube_$* --format $* --size 64x48

$(BAKE_TEST_DIR)/cube_compact.h: $(BAKE_CUBE) assets/checker.png $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_CUBE) -o $@ --name cube_compact --format rgba8888 --size 64x48 --compact

# lines.gltf, written by gen_gltf with the glTF tests' scenes (tests/tests.mk)
BAKE_LINES    := $(BUILD)/gltf/lines.gltf
$(BAKE_TEST_DIR)/lines.h: $(BUILD)/gltf/.ok $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_LINES) -o $@ --name lines --format rgba8888 --size 64x48

BAKE_GLASS    := tests/data/transparency.babylon
BAKE_FOG      := tests/data/fog.babylon
$(BAKE_TEST_DIR)/glass.h: $(BAKE_GLASS) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_GLASS) -o $@ --name glass --format rgba8888 --size 64x48

$(BAKE_TEST_DIR)/fogged.h: $(BAKE_FOG) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_FOG) -o $@ --name fogged --format rgba8888 --size 64x48

# two blended layers in one mesh, drawn with a depth pre-pass
BAKE_PREPASS  := tests/bake/prepass.babylon
$(BAKE_TEST_DIR)/prepass.h: $(BAKE_PREPASS) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_PREPASS) -o $@ --name prepass --format rgba8888 --size 64x48

# the headers baked in the vertex cache's order: NAME.h from BAKE_FILE.NAME,
# with BAKE_OPTS.NAME
BAKE_TORUS    := assets/torus.babylon
BAKE_REORDER  := tests/bake/reorder.babylon
BAKE_ORDERED  := torus reorder reorder_compact
BAKE_FILE.torus           := $(BAKE_TORUS)
BAKE_FILE.reorder         := $(BAKE_REORDER)
BAKE_FILE.reorder_compact := $(BAKE_REORDER)
BAKE_OPTS.reorder_compact := --compact
$(foreach h,$(BAKE_ORDERED),$(eval $(BAKE_TEST_DIR)/$(h).h: $(BAKE_FILE.$(h))))
$(patsubst %,$(BAKE_TEST_DIR)/%.h,$(BAKE_ORDERED)): $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(BAKE_FILE.$(basename $(@F))) -o $@ --name $(basename $(@F)) --format rgba8888 \
	    --size 64x48 $(BAKE_OPTS.$(basename $(@F)))

$(BAKE_TEST_DIR)/test_bake: tests/bake/test_bake.c $(BAKE_TEST_DIR)/baked.h $(BAKE_TEST_DIR)/ortho.h \
        $(BAKE_TEST_DIR)/baked_hidden.h $(BAKE_CUBES) $(BAKE_TEST_DIR)/cube_compact.h \
        $(BAKE_TEST_DIR)/lines.h $(BAKE_TEST_DIR)/glass.h $(BAKE_TEST_DIR)/fogged.h \
        $(BAKE_TEST_DIR)/prepass.h $(patsubst %,$(BAKE_TEST_DIR)/%.h,$(BAKE_ORDERED)) \
        $(BUILD)/tests/obj/unity.o $(LIB) | $(DEPS_OK)
	$(CC) $(TEST_CFLAGS) -I$(BAKE_TEST_DIR) -DMOTE_BAKE_SCENE=\"$(CURDIR)/$(BAKE_SCENE)\" \
	    -DMOTE_BAKE_CUBE=\"$(CURDIR)/$(BAKE_CUBE)\" \
	    -DMOTE_BAKE_ORTHO=\"$(CURDIR)/$(BAKE_ORTHO)\" -DMOTE_BAKE_HIDDEN=\"$(CURDIR)/$(BAKE_HIDDEN)\" \
	    -DMOTE_BAKE_LINES=\"$(CURDIR)/$(BAKE_LINES)\" -DMOTE_BAKE_GLASS=\"$(CURDIR)/$(BAKE_GLASS)\" \
	    -DMOTE_BAKE_FOG=\"$(CURDIR)/$(BAKE_FOG)\" -DMOTE_BAKE_TORUS=\"$(CURDIR)/$(BAKE_TORUS)\" \
	    -DMOTE_BAKE_REORDER=\"$(CURDIR)/$(BAKE_REORDER)\" \
	    -DMOTE_BAKE_PREPASS=\"$(CURDIR)/$(BAKE_PREPASS)\" $< \
	    $(BUILD)/tests/obj/unity.o $(LIB) $(LDFLAGS) $(LDLIBS) -o $@

test-build: $(BAKE_TEST_DIR)/test_bake
TEST_EXTRA += $(BAKE_TEST_DIR)/test_bake
