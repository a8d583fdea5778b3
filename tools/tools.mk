# The command-line tools (tools/*.c -> $(BIN)):
#   mote-render   scene file -> PNG/PPM (tools/mote_render.c)
#   mote-bake     scene file -> C header for firmware (tools/mote_bake.c)
#   gen_assets    writes the project's own assets/ (tools/gen_assets.c)
#   gen_gltf      writes the project's glTF test scenes at test time (tools/gen_gltf.c)
#
#   make tools         build them (part of `make`)
#   make assets        regenerate assets/ with gen_assets (committed outputs)
#   make assets-check  regenerate into $(BUILD) and compare with assets/

MOTE_RENDER := $(BIN)/mote-render
MOTE_BAKE   := $(BIN)/mote-bake
GEN_ASSETS  := $(BIN)/gen_assets
GEN_GLTF    := $(BIN)/gen_gltf
TOOL_OBJ_DIR := $(BUILD)/tools

.PHONY: tools assets assets-check

all: tools
tools: $(MOTE_RENDER) $(MOTE_BAKE) $(GEN_ASSETS) $(GEN_GLTF)

$(TOOL_OBJ_DIR)/%.o: tools/%.c $(wildcard include/mote/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(MOTE_RENDER): $(TOOL_OBJ_DIR)/mote_render.o $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

# mote-bake alone links meshoptimizer (libmeshoptimizer-dev), which orders
# each mesh's triangles and vertices for the firmware's vertex cache.
$(MOTE_BAKE): $(TOOL_OBJ_DIR)/mote_bake.o $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ -lmeshoptimizer $(LDLIBS) -o $@

# gen_assets needs only stb_image_write (in libstb) and libm, not libmote.
$(GEN_ASSETS): $(TOOL_OBJ_DIR)/gen_assets.o
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

# gen_gltf too: it writes its scenes with stb_image_write's PNGs embedded.
$(GEN_GLTF): $(TOOL_OBJ_DIR)/gen_gltf.o
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

assets: $(GEN_ASSETS)
	$(GEN_ASSETS) assets

# The committed assets must be exactly what the generator writes.
assets-check: $(GEN_ASSETS)
	@rm -rf $(BUILD)/assets-check && mkdir -p $(BUILD)/assets-check
	@$(GEN_ASSETS) $(BUILD)/assets-check >/dev/null
	@for f in $(BUILD)/assets-check/*; do \
	    cmp -s "$$f" "assets/$${f##*/}" || { echo "assets-check: assets/$${f##*/} differs from gen_assets output (run make assets)"; exit 1; }; \
	done; echo "assets-check: assets/ matches gen_assets"
