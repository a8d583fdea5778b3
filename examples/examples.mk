# The chapter examples (examples/NN_*.c -> $(BIN)/NN_*) and the demo. The
# tools (mote-render, mote-bake, gen_assets) are built by tools/tools.mk.
#
#   make examples      build them all (part of `make`)
#   make demo          run every chapter example and render the demo scene
#                      (and ../shared/assets/monkey.babylon when present)
#                      into $(OUT)/*.png
#   make demo-images   `make demo`, then copy the README's pictures to docs/images/

EX_SRC      := $(sort $(wildcard examples/[0-9][0-9]_*.c))
EX_NAMES    := $(patsubst examples/%.c,%,$(EX_SRC))
EX_BIN      := $(addprefix $(BIN)/,$(EX_NAMES))
EX_OBJ_DIR  := $(BUILD)/examples
# The examples find assets/ wherever they are run from.
EX_CFLAGS    = $(CFLAGS) -DMOTE_ASSETS=\"$(CURDIR)/assets\"
EX_HEADERS  := $(wildcard include/mote/*.h)

MONKEY      := ../shared/assets/monkey.babylon
DEMO_MODES  := points wireframe flat gouraud textured
DOC_IMAGES  ?= docs/images

.PHONY: examples demo demo-images

examples: $(EX_BIN) tools

$(EX_OBJ_DIR)/%.o: examples/%.c $(EX_HEADERS) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(EX_CFLAGS) -c $< -o $@

$(EX_BIN): $(BIN)/%: $(EX_OBJ_DIR)/%.o $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

demo: examples
	@mkdir -p $(OUT)
	@set -e; for e in $(EX_NAMES); do echo "$(BIN)/$$e $(OUT)"; $(BIN)/$$e $(OUT); done
	$(MOTE_RENDER) assets/demo.babylon -o $(OUT)/demo.png --size 800x600
	@set -e; for m in textured gouraud wireframe; do \
	    echo "$(MOTE_RENDER) assets/demo.babylon -o $(OUT)/demo_$$m.png --size 800x600 --mode $$m"; \
	    $(MOTE_RENDER) assets/demo.babylon -o $(OUT)/demo_$$m.png --size 800x600 --mode $$m; \
	done
	@set -e; if [ -f $(MONKEY) ]; then \
	    for m in $(DEMO_MODES); do \
	        echo "$(MOTE_RENDER) $(MONKEY) -o $(OUT)/monkey_$$m.png --mode $$m"; \
	        $(MOTE_RENDER) $(MONKEY) -o $(OUT)/monkey_$$m.png --mode $$m; \
	    done; \
	else \
	    echo "demo: $(MONKEY) is absent: no $(OUT)/monkey_<mode>.png (the rest is done)"; \
	fi
	@mkdir -p $(OUT)/gltf
	$(GEN_GLTF) $(OUT)/gltf
	$(MOTE_RENDER) $(OUT)/gltf/demo.glb -o $(OUT)/gltf.png --size 800x600
	$(MOTE_RENDER) tests/data/transparency.babylon -o $(OUT)/transparency.png --size 640x480
	$(MOTE_RENDER) tests/data/fog.babylon -o $(OUT)/fog.png --size 640x480 --mip pixel
	$(MOTE_RENDER) tests/data/shiny.babylon -o $(OUT)/specular.png --size 640x360
	$(MOTE_RENDER) tests/data/floor.babylon -o $(OUT)/floor_nomip.png --size 640x360 --mip none
	$(MOTE_RENDER) tests/data/floor.babylon -o $(OUT)/floor_trilinear.png --size 640x360 --mip trilinear
	@echo "demo: images are in $(OUT)/"

# Only pictures of mote's own assets go into the repository.
demo-images: demo
	@mkdir -p $(DOC_IMAGES)
	cp $(OUT)/demo.png $(OUT)/demo_wireframe.png $(OUT)/gltf.png $(OUT)/transparency.png $(OUT)/fog.png $(OUT)/specular.png $(OUT)/floor_nomip.png $(OUT)/floor_trilinear.png $(addprefix $(OUT)/,$(addsuffix .png,$(EX_NAMES))) $(DOC_IMAGES)/
