# The core with MOTE_ENABLE_* options off (see mote.h): tests/options/
# test_options.c built against the core sources once per option, once with
# all seven off and once with every feature (the reference), run by
# tests/options/run.sh as part of `make test`.

OPT_DIR      := $(BUILD)/tests/options
OPT_VARIANTS := full lines binning bilinear subspan vertex_colors falloff orthographic none
OPT_FLAGS.full     :=
OPT_FLAGS.lines    := -DMOTE_ENABLE_LINES=0
OPT_FLAGS.binning  := -DMOTE_ENABLE_BINNING=0
OPT_FLAGS.bilinear := -DMOTE_ENABLE_BILINEAR=0
OPT_FLAGS.subspan  := -DMOTE_ENABLE_SUBSPAN=0
OPT_FLAGS.vertex_colors := -DMOTE_ENABLE_VERTEX_COLORS=0
OPT_FLAGS.falloff  := -DMOTE_ENABLE_LIGHT_FALLOFF=0
OPT_FLAGS.orthographic := -DMOTE_ENABLE_ORTHOGRAPHIC=0
OPT_FLAGS.none     := $(OPT_FLAGS.lines) $(OPT_FLAGS.binning) $(OPT_FLAGS.bilinear) $(OPT_FLAGS.subspan) \
                      $(OPT_FLAGS.vertex_colors) $(OPT_FLAGS.falloff) $(OPT_FLAGS.orthographic)
OPT_BIN      := $(foreach v,$(OPT_VARIANTS),$(OPT_DIR)/test_options_$(v))

$(OPT_DIR)/test_options_%: tests/options/test_options.c tests/support/scenes.c $(CORE_SRC) \
        $(BUILD)/tests/obj/unity.o $(wildcard include/mote/*.h src/core/*.h tests/support/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) $(OPT_FLAGS.$*) tests/options/test_options.c tests/support/scenes.c \
	    $(CORE_SRC) $(BUILD)/tests/obj/unity.o $(LDFLAGS) -lm -o $@

test-build: $(OPT_BIN)
TEST_EXTRA += tests/options/run.sh
