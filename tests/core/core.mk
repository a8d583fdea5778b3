# The render matrix: tests/core/render_matrix.c built against the core
# sources at each optimisation a user may choose, and as the firmware
# profile of embedded/cross.mk, prints one hash per configuration.
#
#   make render-matrix                           writes $(RM_OUT)
#   make render-matrix RENDER_MATRIX_REF=file    and compares it with file
#
# A change that moves code and not pixels keeps every line. (Included by
# the top Makefile's tests/*/*.mk, beside tests/tests.mk.)

RM_DIR      := $(BUILD)/tests/render-matrix
RM_OUT      := $(RM_DIR)/render-matrix.txt
RM_VARIANTS := O3 O2 Os fw
RM_FLAGS.O3 := -O3
RM_FLAGS.O2 := -O2
RM_FLAGS.Os := -Os
RM_FLAGS.fw := -Os -DMOTE_SPECIALISE_SPANS=0 -DMOTE_MAX_DRAWS=8 -DMOTE_ENABLE_LINES=0 \
               -DMOTE_ENABLE_BINNING=0 -DMOTE_ENABLE_BILINEAR=0 -DMOTE_ENABLE_SUBSPAN=0 \
               -DMOTE_ENABLE_VERTEX_COLORS=0 -DMOTE_ENABLE_LIGHT_FALLOFF=0 \
               -DMOTE_ENABLE_ORTHOGRAPHIC=0 -DMOTE_ENABLE_EMISSIVE=0 -DMOTE_ENABLE_ALPHA_TEST=0 \
               -DMOTE_ENABLE_BLEND=0 -DMOTE_ENABLE_SPECULAR=0 -DMOTE_ENABLE_FOG=0 -DMOTE_ENABLE_MIPMAPS=0 \
                 -DMOTE_ENABLE_EMISSIVE_MAP=0 -DMOTE_ENABLE_OPACITY_MAP=0 -DMOTE_ENABLE_SPECULAR_MAP=0
RM_BIN      := $(foreach v,$(RM_VARIANTS),$(RM_DIR)/render_matrix_$(v))
RENDER_MATRIX_REF ?=

.PHONY: render-matrix
$(RM_DIR)/render_matrix_%: tests/core/render_matrix.c tests/support/scenes.c $(CORE_SRC) \
        $(wildcard include/mote/*.h src/core/*.h tests/support/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) -std=c99 -g -ffp-contract=off $(WARN) -Iinclude -Isrc -Itests $(RM_FLAGS.$*) \
	    tests/core/render_matrix.c tests/support/scenes.c $(CORE_SRC) -lm -o $@

render-matrix: $(RM_BIN)
	@rm -f $(RM_OUT)
	@for v in $(RM_VARIANTS); do $(RM_DIR)/render_matrix_$$v $$v >> $(RM_OUT) || exit 1; done
	@echo "render matrix: $$(wc -l < $(RM_OUT)) configurations in $(RM_OUT)"
	@if [ -n "$(RENDER_MATRIX_REF)" ]; then \
	    if cmp -s $(RM_OUT) $(RENDER_MATRIX_REF); then echo "render matrix: identical to $(RENDER_MATRIX_REF)"; \
	    else diff $(RENDER_MATRIX_REF) $(RM_OUT) | head -n 20; \
	         echo "render matrix: DIFFERS from $(RENDER_MATRIX_REF)"; exit 1; fi; fi

# No two core files call each other (tests/core/layers.sh), run by make test.
TEST_EXTRA += tests/core/layers.sh
