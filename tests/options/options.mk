# The core with MOTE_ENABLE_* options off (see mote.h): tests/options/
# test_options.c built against the core sources once per option that
# refuses or has layers, once with every option off ("none": the others,
# drawn without and counted or ignored, are checked there) and once with
# every feature (the reference), run by
# tests/options/run.sh as part of `make test`. The vector loops are left
# out (MOTE_SIMD=0): they draw the scalar loops' bytes, and twelve copies
# of them doubled the time these builds take. So are span.c's specialised
# loops (a minute of compiling each) except in the full and none builds.

OPT_DIR      := $(BUILD)/tests/options
OPT_VARIANTS := full lines binning bilinear subspan vertex_colors falloff orthographic emissive_map opacity_map \
                specular_map none
OPT_FLAGS.full     :=
OPT_FLAGS.lines    := -DMOTE_ENABLE_LINES=0
OPT_FLAGS.binning  := -DMOTE_ENABLE_BINNING=0
OPT_FLAGS.bilinear := -DMOTE_ENABLE_BILINEAR=0
OPT_FLAGS.subspan  := -DMOTE_ENABLE_SUBSPAN=0
OPT_FLAGS.vertex_colors := -DMOTE_ENABLE_VERTEX_COLORS=0
OPT_FLAGS.falloff  := -DMOTE_ENABLE_LIGHT_FALLOFF=0
OPT_FLAGS.orthographic := -DMOTE_ENABLE_ORTHOGRAPHIC=0
OPT_FLAGS.emissive_map := -DMOTE_ENABLE_EMISSIVE_MAP=0
OPT_FLAGS.opacity_map  := -DMOTE_ENABLE_OPACITY_MAP=0
OPT_FLAGS.specular_map := -DMOTE_ENABLE_SPECULAR_MAP=0
OPT_FLAGS.none     := $(OPT_FLAGS.lines) $(OPT_FLAGS.binning) $(OPT_FLAGS.bilinear) $(OPT_FLAGS.subspan) \
                      $(OPT_FLAGS.vertex_colors) $(OPT_FLAGS.falloff) $(OPT_FLAGS.orthographic) \
                      $(OPT_FLAGS.emissive_map) $(OPT_FLAGS.opacity_map) $(OPT_FLAGS.specular_map) \
                      -DMOTE_ENABLE_ALPHA_TEST=0 -DMOTE_ENABLE_BLEND=0 -DMOTE_ENABLE_SPECULAR=0 \
                      -DMOTE_ENABLE_FOG=0 -DMOTE_ENABLE_MIPMAPS=0 -DMOTE_ENABLE_EMISSIVE=0
OPT_BIN      := $(foreach v,$(OPT_VARIANTS),$(OPT_DIR)/test_options_$(v))

$(OPT_DIR)/test_options_%: tests/options/test_options.c tests/support/scenes.c $(CORE_SRC) \
        $(BUILD)/tests/obj/unity.o $(wildcard include/mote/*.h src/core/*.h tests/support/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) -DMOTE_SIMD=0 $(if $(filter full none,$*),,-DMOTE_SPECIALISE_SPANS=0) \
	    $(OPT_FLAGS.$*) tests/options/test_options.c tests/support/scenes.c \
	    $(CORE_SRC) $(BUILD)/tests/obj/unity.o $(LDFLAGS) -lm -o $@

test-build: $(OPT_BIN)
TEST_EXTRA += tests/options/run.sh
