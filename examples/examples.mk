# The chapter examples (examples/NN_*.c -> $(BIN)/NN_*), the mote-render
# command line, and the asset generator (tools/gen_assets.c).
#
#   make examples      build them all (part of `make`)
#   make demo          run every chapter example and render the demo scene
#                      (and ../shared/assets/monkey.babylon when present)
#                      into $(OUT)/*.png
#   make demo-images   `make demo`, then copy the README's pictures to docs/images/
#   make assets        regenerate assets/ with gen_assets (committed outputs)
#   make assets-check  regenerate into $(BUILD) and compare with assets/

EX_SRC      := $(sort $(wildcard examples/[0-9][0-9]_*.c))
EX_NAMES    := $(patsubst examples/%.c,%,$(EX_SRC))
EX_BIN      := $(addprefix $(BIN)/,$(EX_NAMES))
EX_OBJ_DIR  := $(BUILD)/examples
MOTE_RENDER := $(BIN)/mote-render
GEN_ASSETS  := $(BIN)/gen_assets
# The examples find assets/ wherever they are run from.
EX_CFLAGS    = $(CFLAGS) -DMOTE_ASSETS=\"$(CURDIR)/assets\"
EX_HEADERS  := $(wildcard include/mote/*.h)

MONKEY      := ../shared/assets/monkey.babylon
DEMO_MODES  := points wireframe flat gouraud textured
DOC_IMAGES  ?= docs/images

.PHONY: examples demo demo-images assets assets-check

examples: $(EX_BIN) $(MOTE_RENDER) $(GEN_ASSETS)

$(EX_OBJ_DIR)/%.o: examples/%.c $(EX_HEADERS) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(EX_CFLAGS) -c $< -o $@

$(EX_OBJ_DIR)/gen_assets.o: tools/gen_assets.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(EX_BIN): $(BIN)/%: $(EX_OBJ_DIR)/%.o $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

$(MOTE_RENDER): $(EX_OBJ_DIR)/mote_render.o $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

# gen_assets needs only stb_image_write (in libstb) and libm, not libmote.
$(GEN_ASSETS): $(EX_OBJ_DIR)/gen_assets.o
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
	@echo "demo: images are in $(OUT)/"

# Only pictures of mote's own assets go into the repository.
demo-images: demo
	@mkdir -p $(DOC_IMAGES)
	cp $(OUT)/demo.png $(OUT)/demo_wireframe.png $(addprefix $(OUT)/,$(addsuffix .png,$(EX_NAMES))) $(DOC_IMAGES)/
