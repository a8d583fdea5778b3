# make bench-embedded: instructions per frame of the firmware example on the
# emulated boards, counted by a TCG plugin of our own (embedded/qemu/), with
# RAM, flash and stack beside them (embedded/bench-embedded.sh; the
# variants it runs are FW_BENCH_VARIANTS in embedded/cross.mk).

INSN_COUNT_PLUGIN := $(BUILD)/qemu/libinsn_count.so

.PHONY: bench-embedded insn-count-plugin

# A plugin is loaded into qemu: plain host flags, never the sanitizers.
$(INSN_COUNT_PLUGIN): embedded/qemu/insn_count.c embedded/bench.mk
	@mkdir -p $(dir $@)
	$(CC) -std=c99 -O2 $(WARN) -fPIC -shared -fvisibility=hidden $< -o $@

insn-count-plugin: $(INSN_COUNT_PLUGIN)

bench-embedded:
	@MOTE_BUILD=$(BUILD) MOTE_SUZANNE=$(FW_SCENE.suzanne) sh embedded/bench-embedded.sh $(FW_BENCH_VARIANTS)
