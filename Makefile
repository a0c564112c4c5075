# raytrace: a ray tracer for the course scene format.
#
# make              build ./raytrace, ./raytrace-diff and ./raytrace-merge
#                   (with OpenMP when the compiler has it)
# make test         build and run the quick suite (a minute or two on 2 cores)
# make check        build and run every suite in full (CI runs it)
# make test-windows cross-build the Windows programs (MinGW-w64) and test them
#                   under Wine; make test-musl the same for a musl build
#                   (tests/platform.sh); make CC=x86_64-w64-mingw32-gcc
#                   builds raytrace.exe and its tools here
# make OPENMP=0     build without OpenMP
# make REAL=float   build with single-precision geometry (not exact: see
#                   docs/trade.md); $(BUILD)/raytrace-float is that build too
# make install      install the commands and man pages under $(DESTDIR)$(PREFIX)
#                   (PREFIX defaults to /usr/local); make uninstall removes them
# make gallery      render every example scene to docs/gallery/*.png
# make samples      write README.md's samples of what the programs print
# make bench        measure speed on generated scenes; writes docs/benchmarks.md
#                   (BENCH_RUNS=N runs each, BENCH_ONLY="course ..." a subset)
# make race         only its race against the exact Embree renderer, scaling
#                   and shapes' fields (tests/bench/anchor.sh)
# make mpl MPL=DIR  render the MPL ray tracer's four scenes (DIR: a checkout of
#                   its program's repository) and compare them with its renders
# make trade        measure error against time for every speed/accuracy knob;
#                   writes docs/trade.md and docs/trade-*.svg (and make
#                   trade-cache's page)
# make trade-cache  the irradiance cache against uniform sampling and
#                   --noise: docs/gicache.md and docs/gicache.svg
# make fuzz         fuzz every parser with libFuzzer (clang), FUZZ_TIME seconds
#                   each (default 60); tests/fuzz/fuzz.sh says more
# make fuzz-long    the same, 30 minutes a parser, with totals
# make memcheck     renders and comparisons under Valgrind's memcheck
# make report       the course report, report/report.pdf from report/report.md
#                   (needs pandoc, xelatex, rsvg-convert and Graphviz's dot)
# CFLAGS, CPPFLAGS, LDFLAGS and LDLIBS are yours: the flags the build needs
# are kept apart in RT_* variables, so `make CFLAGS=-O0` cannot drop them.
# The default -O3 is faster than -O2 on the sphere field (same bytes;
# docs/log.md); it leaves out debugging information, which
# `make CFLAGS="-O3 -g"` adds (a fresh build takes longer with it).

CC ?= cc
# Make's own default, cc, is not on every system (MSYS2's MinGW shells
# have gcc alone).
ifeq ($(origin CC),default)
CC := $(shell command -v cc >/dev/null 2>&1 && echo cc || echo gcc)
endif

CFLAGS ?= -O3
# Link-time optimisation of the hot path, when $(CC) can do it: a ray runs
# through several modules (render/trace.c, shade.c, visibility.c, the
# shapes' tests), which LTO inlines into one another (docs/log.md measures
# glass.txt without it). LTO holds the flags, empty for none; they
# apply to the objects of the layers a ray runs through (math, geometry,
# accel, scene, render) and to raytrace's link alone. Those objects keep
# their plain code too (fat objects, GCC's), which the tests and the other
# tools link as they are: a fresh make test builds in half the time. The
# same bytes either way. The probe fails where a flag is only warned of
# (clang ignores -ffat-lto-objects): such a compiler builds without LTO.
LTO_TRY = printf 'int main(void){return 0;}\n' | $(CC) -Werror $(1) -x c - -o /dev/null >/dev/null 2>&1
ifeq ($(origin LTO),undefined)
LTO := $(shell $(call LTO_TRY,-flto=auto -ffat-lto-objects) && echo -flto=auto -ffat-lto-objects)
endif

BUILD ?= build

# The system the programs are for (src/base/ has a POSIX and a Windows
# implementation of each platform call): Windows when $(CC) makes Windows
# programs (MinGW-w64, from Linux or in MSYS2), else POSIX. Windows
# programs are named NAME.exe and linked statically, so that they run
# without the toolchain's DLLs; its C library's printf and strtod are
# MinGW-w64's own, which round exactly as glibc's and musl's do.
TARGET := $(shell $(CC) -dumpmachine 2>/dev/null)
ifneq ($(filter %mingw32 %windows %cygwin %msys,$(TARGET)),)
PLATFORM := win32
EXE := .exe
RT_PLATFORM := -D__USE_MINGW_ANSI_STDIO=1
RT_PLATFORM_LDFLAGS := -static
RT_PLATFORM_LIBS := -lpsapi -lshell32
# A Windows program is run by the probes below only on Windows itself.
CROSS := $(if $(filter MINGW% MSYS% CYGWIN%,$(shell uname -s 2>/dev/null)),,1)
else
PLATFORM := posix
EXE :=
RT_PLATFORM :=
RT_PLATFORM_LDFLAGS :=
RT_PLATFORM_LIBS :=
CROSS :=
endif
OTHER_PLATFORM := $(if $(filter win32,$(PLATFORM)),posix,win32)

# Probe: can $(CC) compile and link an OpenMP program, and (unless it is a
# cross-build) does that program start? A toolchain whose OpenMP library
# cannot be loaded (musl-gcc finds glibc's libgomp) gives a serial build.
HASH := \#
OPENMP_PROBE_EXE := $(BUILD)/.openmp-probe-$$$$$(EXE)
OPENMP_PROBE := $(shell mkdir -p $(BUILD) && \
	printf '$(HASH)include <omp.h>\nint main(void){return omp_get_max_threads() < 1;}\n' \
	| $(CC) -fopenmp $(RT_PLATFORM_LDFLAGS) -x c - -o $(OPENMP_PROBE_EXE) >/dev/null 2>&1 \
	&& { [ -n '$(CROSS)' ] || $(OPENMP_PROBE_EXE) >/dev/null 2>&1; } && echo 1 || echo 0; \
	rm -f $(OPENMP_PROBE_EXE))
ifeq ($(origin OPENMP),undefined)
ifeq ($(OPENMP_PROBE),0)
ifeq ($(filter clean,$(MAKECMDGOALS)),)
$(info make: $(CC) has no OpenMP that links and runs: building serial programs (one thread; OPENMP=1 forces it))
endif
endif
endif
OPENMP ?= $(OPENMP_PROBE)
export OPENMP # the suites' own makes need not probe again
ifeq ($(OPENMP),1)
RT_OMP := -fopenmp
else
RT_OMP :=
endif

# The geometry's floating-point type (include/math/real.h): double, or float to
# measure what single precision costs (docs/trade.md).
REAL ?= double
ifeq ($(REAL),float)
RT_REAL := -DRAYTRACE_REAL_FLOAT
else ifeq ($(REAL),double)
RT_REAL :=
else
$(error REAL must be double or float, not '$(REAL)')
endif

RT_CFLAGS := -std=c11 -Wall -Wextra -pedantic -ffp-contract=off $(RT_OMP) $(RT_REAL)
RT_CPPFLAGS := -Iinclude -MMD -MP $(RT_PLATFORM)
RT_LDFLAGS := $(RT_PLATFORM_LDFLAGS)
RT_LDLIBS := -lm $(RT_PLATFORM_LIBS)

# One folder per layer (docs/design.md): src/LAYER/NAME.c, its header
# include/LAYER/NAME.h. The commands' own files are in src/cli.
LIB_SRC := $(sort $(filter-out src/cli/% src/base/%_$(OTHER_PLATFORM).c,$(wildcard src/*/*.c)))
LIB_OBJ := $(LIB_SRC:src/%.c=$(BUILD)/%.o)
RAYTRACE_OBJ := $(BUILD)/cli/main.o $(BUILD)/cli/options.o $(BUILD)/cli/adjust.o \
	$(BUILD)/cli/summary.o $(BUILD)/cli/args.o

# On x86, the hierarchy's queries are built a second time for processors
# with AVX2 and FMA (src/accel/bvh_query.h), and run on those processors.
X86 := $(if $(filter x86_64-% i386-% i486-% i586-% i686-%,$(TARGET)),1)
ifeq ($(X86),1)
RT_CPPFLAGS += -DRAYTRACE_AVX2
LIB_OBJ += $(BUILD)/accel/bvh_query_avx2.o
endif
AVX2_FLAGS := -mavx2 -mfma -DBVH_QUERY_AVX2
# GCC aligns no Windows stack to the 32 bytes AVX's aligned moves need
# (GCC bug 54412): the assembler makes them unaligned moves, as fast.
ifeq ($(PLATFORM),win32)
AVX2_FLAGS += -Wa,-muse-unaligned-vector-move
endif

# Objects are rebuilt when the flags change (say, OPENMP=0 or a sanitizer).
FLAGS_STAMP := $(BUILD)/flags
FLAGS_NOW := $(CC) $(RT_CPPFLAGS) $(CPPFLAGS) $(RT_CFLAGS) $(CFLAGS) $(LTO) $(RT_LDFLAGS) $(LDFLAGS) $(LDLIBS) $(AVX2_FLAGS)
ifneq ($(shell cat $(FLAGS_STAMP) 2>/dev/null),$(strip $(FLAGS_NOW)))
$(shell mkdir -p $(BUILD) && echo '$(strip $(FLAGS_NOW))' > $(FLAGS_STAMP))
endif

TEST_SRC := $(sort $(wildcard tests/test_*.c)) tests/unit.c
# The unit suites, one a file: tests/test_NAME.c defines NAME_tests[], and
# unit.c runs every suite of this list, rewritten when the files change.
UNIT_SUITES := $(patsubst tests/test_%.c,X(%),$(filter tests/test_%,$(TEST_SRC)))
SUITES_H := $(BUILD)/tests/suites.h
ifneq ($(shell cat $(SUITES_H) 2>/dev/null),$(UNIT_SUITES))
$(shell mkdir -p $(BUILD)/tests && echo '$(UNIT_SUITES)' > $(SUITES_H))
endif
FUZZ_TARGETS := course keyword mpl obj ply stl mtl ppm picture jpeg tile
TEST_OBJ := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%.o)

PREFIX ?= /usr/local
BINDIR := $(PREFIX)/bin
MANDIR := $(PREFIX)/share/man/man1
PROGRAMS := raytrace raytrace-diff raytrace-merge
MANPAGES := docs/raytrace.1 docs/raytrace-diff.1 docs/raytrace-merge.1
SCENES := $(wildcard scenes/*.txt)
GALLERY := $(SCENES:scenes/%.txt=docs/gallery/%.png) docs/gallery/indirect-ao16.png \
	docs/gallery/indirect-gi16.png docs/gallery/indirect-gi256.png \
	docs/gallery/mpl-modelphysical.png docs/gallery/materials-noise4maxspp1024.png \
	docs/gallery/horizon-texturefilterbilinear.png docs/gallery/materials-texturefilterbilinear.png \
	docs/gallery/room-gi16passindirect.png docs/gallery/indirect-ao16passao.png \
	docs/gallery/indirect-passalbedo.png docs/gallery/indirect-passnormal.png \
	docs/gallery/indirect-passdepth.png

.PHONY: all test check clean install uninstall gallery bench race trade trade-cache report fuzz fuzz-long memcheck mpl

# The programs go to OUT (default: here), named NAME.exe on Windows; NAME
# stands for them in the rules. make test-musl builds its own in a folder
# of the build (OUT=$(BUILD)/musl).
OUT ?= .
all: $(OUT)/raytrace$(EXE) $(OUT)/raytrace-diff$(EXE) $(OUT)/raytrace-merge$(EXE)

ifneq ($(OUT)/$(EXE),./)
.PHONY: raytrace raytrace-diff raytrace-merge
raytrace raytrace-diff raytrace-merge: %: $(OUT)/%$(EXE)
endif

# The hot path's objects, compiled for LTO (above), and raytrace linked with
# it ("private": its prerequisites do not inherit it).
HOT_OBJ := $(filter $(foreach l,math geometry accel scene render,$(BUILD)/$(l)/%),$(LIB_OBJ))
$(HOT_OBJ): RT_LTO = $(LTO)
$(OUT)/raytrace$(EXE): private RT_LTO = $(LTO)

$(OUT)/raytrace$(EXE): $(RAYTRACE_OBJ) $(LIB_OBJ)
	$(CC) $(RT_CFLAGS) $(CFLAGS) $(RT_LTO) $(RT_LDFLAGS) $(LDFLAGS) -o $@ $^ $(RT_LDLIBS) $(LDLIBS)

$(BUILD)/unit$(EXE): $(TEST_OBJ) $(LIB_OBJ)
	$(CC) $(RT_CFLAGS) $(CFLAGS) $(RT_LDFLAGS) $(LDFLAGS) -o $@ $^ $(RT_LDLIBS) $(LDLIBS)

# raytrace-diff and raytrace-merge need images alone: the layers below
# geometry (link-time optimisation then reads a third of the objects).
TOOL_OBJ := $(filter $(BUILD)/base/% $(BUILD)/math/% $(BUILD)/image/%,$(LIB_OBJ))

$(OUT)/raytrace-diff$(EXE): $(BUILD)/cli/diff_main.o $(BUILD)/cli/args.o $(TOOL_OBJ)
	$(CC) $(RT_CFLAGS) $(CFLAGS) $(RT_LDFLAGS) $(LDFLAGS) -o $@ $^ $(RT_LDLIBS) $(LDLIBS)

$(OUT)/raytrace-merge$(EXE): $(BUILD)/cli/merge_main.o $(BUILD)/cli/args.o $(TOOL_OBJ)
	$(CC) $(RT_CFLAGS) $(CFLAGS) $(RT_LDFLAGS) $(LDFLAGS) -o $@ $^ $(RT_LDLIBS) $(LDLIBS)

# The fault injector tests/faults.sh preloads (test-only, glibc): built with
# flags of its own, since a sanitizer's runtime cannot be preloaded.
$(BUILD)/inject.so: tests/inject.c
	@mkdir -p $(@D)
	$(CC) -std=c11 -O1 -g -shared -fPIC -o $@ $< -ldl

$(BUILD)/%.o: src/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(RT_CPPFLAGS) $(CPPFLAGS) $(RT_CFLAGS) $(CFLAGS) $(RT_LTO) -c -o $@ $<

$(BUILD)/accel/bvh_query_avx2.o: src/accel/bvh_query.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(RT_CPPFLAGS) $(CPPFLAGS) $(RT_CFLAGS) $(CFLAGS) $(RT_LTO) $(AVX2_FLAGS) -c -o $@ $<

$(BUILD)/tests/%.o: tests/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(RT_CPPFLAGS) -Itests $(CPPFLAGS) $(RT_CFLAGS) $(CFLAGS) -c -o $@ $<

$(BUILD)/tests/unit.o: tests/unit.c $(SUITES_H) $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(RT_CPPFLAGS) -Itests -I$(BUILD)/tests $(CPPFLAGS) $(RT_CFLAGS) $(CFLAGS) -c -o $@ $<

# make test, README's second command: the quick suite, a minute and a
# quarter on two cores from a fresh clone, build included: the unit tests, the golden
# render of every example scene (and the course scene against its
# reference), the command line and its errors, and a sample of each longer
# suite (tiles, injected faults, JPEGs). make check: every suite in full,
# the fuzz targets replaying their inputs and the single-precision build
# besides (CI runs it). Both run the suites side by side, one a processor
# unless make -jN says otherwise; each suite in its own temporary folder,
# its output shown whole when it ends (-Otarget).
NPROC := $(shell nproc 2>/dev/null || echo 2)
TEST_JOBS = $(if $(findstring -j,$(MAKEFLAGS)),,-j$(NPROC))
TEST_LEVEL ?= full
# In the order make starts them: raytrace's objects and link first, then
# the longest suites first.
QUICK_SUITES := golden cli report unit jpeg faults meshes hostile tiles noise install layers
FULL_SUITES := $(QUICK_SUITES) replay
.PHONY: $(FULL_SUITES:%=test-%)

# Every suite runs, whichever fails (make -k); the last line names those
# that failed, and the exit status is make's own.
FAILED_SUITES := $(BUILD)/tests/failed
SUITE_FAILED = { mkdir -p $(BUILD)/tests && echo $(@:test-%=%) >>$(FAILED_SUITES); exit 1; }
RUN_SUITES = rm -f $(FAILED_SUITES); \
	$(MAKE) --no-print-directory -k $(TEST_JOBS) -Otarget $(1) && exit 0; \
	echo "make: suites failed: $$(tr '\n' ' ' <$(FAILED_SUITES) 2>/dev/null)(and any build error above)" >&2; \
	exit 1
test:
	@$(call RUN_SUITES,TEST_LEVEL=quick $(QUICK_SUITES:%=test-%))

check:
	@$(call RUN_SUITES,TEST_LEVEL=full RT_FLOAT=$(BUILD)/raytrace-float $(FULL_SUITES:%=test-%))

# One suite each (make test-NAME runs it alone, in full unless
# TEST_LEVEL=quick).
SUITE_ENV = RAYTRACE_TEST_LEVEL=$(TEST_LEVEL)
test-unit: $(BUILD)/unit$(EXE)
	$(SUITE_ENV) $(BUILD)/unit$(EXE) || $(SUITE_FAILED)
test-replay: $(FUZZ_TARGETS:%=$(BUILD)/replay/%)
	@for t in $(FUZZ_TARGETS); do (cd scenes && ../$(BUILD)/replay/$$t \
		$$(ls -d ../tests/fuzz/corpus/$$t/* ../tests/fuzz/regress/$$t/* 2>/dev/null)) || $(SUITE_FAILED); done
test-golden: raytrace raytrace-diff
	$(SUITE_ENV) sh tests/golden.sh ./raytrace ./raytrace-diff || $(SUITE_FAILED)
test-cli: raytrace raytrace-diff raytrace-merge $(RT_FLOAT)
	$(SUITE_ENV) RT_FLOAT=$(RT_FLOAT) sh tests/cli.sh ./raytrace ./raytrace-diff || $(SUITE_FAILED)
test-meshes: raytrace raytrace-diff $(BUILD)/meshgen
	$(SUITE_ENV) sh tests/meshes.sh ./raytrace ./raytrace-diff $(BUILD)/meshgen || $(SUITE_FAILED)
test-hostile: raytrace
	$(SUITE_ENV) sh tests/hostile.sh ./raytrace || $(SUITE_FAILED)
test-install: raytrace raytrace-diff raytrace-merge
	$(SUITE_ENV) sh tests/install.sh || $(SUITE_FAILED)
test-layers: raytrace raytrace-diff raytrace-merge
	$(SUITE_ENV) BUILD=$(BUILD) sh tests/layers.sh || $(SUITE_FAILED)
test-report:
	$(SUITE_ENV) sh tests/report.sh || $(SUITE_FAILED)
test-jpeg: raytrace raytrace-diff
	$(SUITE_ENV) sh tests/jpeg.sh ./raytrace ./raytrace-diff || $(SUITE_FAILED)
test-tiles: raytrace raytrace-merge
	$(SUITE_ENV) sh tests/tiles.sh ./raytrace ./raytrace-merge || $(SUITE_FAILED)
test-noise: raytrace raytrace-diff raytrace-merge
	$(SUITE_ENV) sh tests/noise.sh ./raytrace ./raytrace-diff ./raytrace-merge || $(SUITE_FAILED)
test-faults: raytrace $(BUILD)/inject.so
	$(SUITE_ENV) sh tests/faults.sh ./raytrace $(BUILD)/inject.so || $(SUITE_FAILED)

# The programs of another system and another C library, against this
# build's bytes (tests/platform.sh): Windows's, cross-built by MinGW-w64
# (Debian: gcc-mingw-w64-x86-64) and run under Wine (Debian: wine64), and
# musl's (Debian: musl-tools). Not in make test or make check, which stay
# on this system: CI runs both. Each is built by a make of its own, which
# probes its compiler's OpenMP again.
MINGW_CC ?= x86_64-w64-mingw32-gcc
MUSL_CC ?= musl-gcc
.PHONY: test-windows test-musl
test-windows: raytrace
	env -u OPENMP $(MAKE) --no-print-directory CC=$(MINGW_CC) BUILD=$(BUILD)/windows all \
		$(BUILD)/windows/unit.exe
	$(SUITE_ENV) sh tests/platform.sh windows . $(BUILD)/windows/unit.exe ./raytrace
test-musl: raytrace
	env -u OPENMP $(MAKE) --no-print-directory CC=$(MUSL_CC) BUILD=$(BUILD)/musl OUT=$(BUILD)/musl \
		all $(BUILD)/musl/unit
	$(SUITE_ENV) sh tests/platform.sh musl $(BUILD)/musl $(BUILD)/musl/unit ./raytrace

install: $(PROGRAMS:%=$(OUT)/%$(EXE))
	install -d '$(DESTDIR)$(BINDIR)' '$(DESTDIR)$(MANDIR)'
	install -m 755 $(PROGRAMS:%=$(OUT)/%$(EXE)) '$(DESTDIR)$(BINDIR)'
	install -m 644 $(MANPAGES) '$(DESTDIR)$(MANDIR)'

uninstall:
	rm -f $(PROGRAMS:%='$(DESTDIR)$(BINDIR)'/%$(EXE)) $(MANPAGES:docs/%='$(DESTDIR)$(MANDIR)'/%)

# The README's samples of what the programs print, printed by them
# (docs/samples.sh; tests/cli.sh checks that they are today's).
.PHONY: samples
samples: raytrace raytrace-diff raytrace-merge
	sh docs/samples.sh README.md

# The README's pictures, rendered from the scenes so that they stay true
# (tests/cli.sh checks that each has the pixels of its scene's render).
gallery: $(GALLERY)

docs/gallery/%.png: scenes/%.txt raytrace
	@mkdir -p $(@D)
	./raytrace -q $< $@

# The same room without and with ambient occlusion and global illumination:
# docs/gallery/indirect-OPTS.png is scenes/indirect.txt rendered with OPTS
# (the options without their spaces and dashes, as tests/cli.sh reads them).
docs/gallery/indirect-ao16.png: scenes/indirect.txt raytrace
	./raytrace -q --ao 16 $< $@
docs/gallery/indirect-gi16.png: scenes/indirect.txt raytrace
	./raytrace -q --gi 16 $< $@
docs/gallery/indirect-gi256.png: scenes/indirect.txt raytrace
	./raytrace -q --gi 256 $< $@
# Adaptive sampling, and the map of where its samples went (written beside
# it; tests/noise.sh checks that the map is the render's).
docs/gallery/materials-noise4maxspp1024.png: scenes/materials.txt raytrace
	./raytrace -q --noise 4 --max-spp 1024 --spp-map $(@:.png=-spp.png) $< $@
# Texture filtering: the scenes as they were without it (bilinear lookups
# at a point), beside their default renders.
docs/gallery/%-texturefilterbilinear.png: scenes/%.txt raytrace
	./raytrace -q --texture-filter bilinear $< $@
# One part of a picture alone (--pass): the room's gathered light, and the
# parts of the indirect room read off its surfaces.
docs/gallery/room-gi16passindirect.png: scenes/room.txt raytrace
	./raytrace -q --gi 16 --pass indirect $< $@
docs/gallery/indirect-ao16passao.png: scenes/indirect.txt raytrace
	./raytrace -q --ao 16 --pass ao $< $@
docs/gallery/indirect-pass%.png: scenes/indirect.txt raytrace
	./raytrace -q --pass $* $< $@
# The MPL ray tracer's example by our physical model, beside its program's.
docs/gallery/mpl-modelphysical.png: scenes/mpl.txt raytrace
	./raytrace -q --model physical $< $@

# The single-precision build beside the double one, for `make trade`.
FLOAT_OBJ := $(RAYTRACE_OBJ:$(BUILD)/%.o=$(BUILD)/float/%.o) $(LIB_OBJ:$(BUILD)/%.o=$(BUILD)/float/%.o)

$(BUILD)/float/%.o: src/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(RT_CPPFLAGS) $(CPPFLAGS) $(RT_CFLAGS) -DRAYTRACE_REAL_FLOAT $(CFLAGS) -c -o $@ $<

$(BUILD)/float/accel/bvh_query_avx2.o: src/accel/bvh_query.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(RT_CPPFLAGS) $(CPPFLAGS) $(RT_CFLAGS) -DRAYTRACE_REAL_FLOAT $(CFLAGS) $(AVX2_FLAGS) \
		-c -o $@ $<

$(BUILD)/raytrace-float: $(FLOAT_OBJ)
	$(CC) $(RT_CFLAGS) $(CFLAGS) $(RT_LDFLAGS) $(LDFLAGS) -o $@ $^ $(RT_LDLIBS) $(LDLIBS)

# The benchmark (not a test): generated scenes, medians, docs/benchmarks.md.
# The meshes of tests/meshes.sh and the benchmark, in every mesh format.
$(BUILD)/meshgen: tests/meshgen.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(CFLAGS) $(RT_LDFLAGS) $(LDFLAGS) -o $@ tests/meshgen.c $(RT_LDLIBS) $(LDLIBS)

$(BUILD)/scenegen: tests/bench/scenegen.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(CFLAGS) $(RT_LDFLAGS) $(LDFLAGS) -o $@ tests/bench/scenegen.c $(RT_LDLIBS) $(LDLIBS)

# raytrace with Embree 3's traversal in place of ours (tests/bench/embree_bvh.c),
# which the benchmark races against ours when libembree-dev is installed.
EMBREE_OBJ := $(RAYTRACE_OBJ) $(filter-out $(BUILD)/accel/bvh%,$(LIB_OBJ)) $(BUILD)/embree/embree_bvh.o
EMBREE_PROBE = printf '$(HASH)include <embree3/rtcore.h>\nint main(void){return !rtcNewDevice(0);}\n' \
	| $(CC) -x c - -o /dev/null -lembree3 >/dev/null 2>&1

$(BUILD)/embree/embree_bvh.o: tests/bench/embree_bvh.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(RT_CPPFLAGS) $(CPPFLAGS) $(RT_CFLAGS) $(CFLAGS) -c -o $@ $<

$(BUILD)/raytrace-embree: $(EMBREE_OBJ)
	$(CC) $(RT_CFLAGS) $(CFLAGS) $(RT_LDFLAGS) $(LDFLAGS) -o $@ $^ -lembree3 $(RT_LDLIBS) $(LDLIBS)

bench: raytrace raytrace-diff $(BUILD)/scenegen
	@if $(EMBREE_PROBE); then $(MAKE) --no-print-directory $(BUILD)/raytrace-embree; \
	else rm -f $(BUILD)/raytrace-embree; \
	echo "bench: no Embree 3 (libembree-dev): no race against its traversal" >&2; fi
	BENCH_EMBREE=$(BUILD)/raytrace-embree sh tests/bench/bench.sh ./raytrace ./raytrace-diff \
		$(BUILD)/scenegen
	sh tests/bench/anchor.sh ./raytrace ./raytrace-diff $(BUILD)/scenegen

# The race against the exact Embree renderer (BENCH_ANCHOR, default
# ../shared/anchors/embree), the scaling and the shapes' fields alone: the
# section of docs/benchmarks.md that tests/bench/anchor.sh writes.
race: raytrace raytrace-diff $(BUILD)/scenegen
	sh tests/bench/anchor.sh ./raytrace ./raytrace-diff $(BUILD)/scenegen

# The course report: its class diagram checked against the code
# (report/classes.sh), its quoted tables brought up to date from the pages
# that measure them (report/quote.sh), the module graph of docs/design.md
# written again from the code (docs/modules.sh), the diagrams drawn by Graphviz, the PDF
# (A4, at most 6 pages) by pandoc and XeLaTeX (SVG figures through
# rsvg-convert). Without those tools it says which are missing and fails.
REPORT_TOOLS := pandoc:pandoc xelatex:texlive-xetex rsvg-convert:librsvg2-bin dot:graphviz
report:
	@missing=; for t in $(REPORT_TOOLS); do command -v $${t%%:*} >/dev/null 2>&1 || \
		missing="$$missing $${t%%:*} (Debian: $${t#*:})"; done; \
	if [ -n "$$missing" ]; then echo "make report: missing:$$missing" >&2; exit 1; fi
	sh report/classes.sh
	sh report/quote.sh >report/report.md.new && mv report/report.md.new report/report.md
	sh docs/modules.sh >docs/modules.dot
	dot -Tsvg docs/modules.dot -o docs/modules.svg
	dot -Tsvg report/classes.dot -o report/classes.svg
	dot -Tsvg report/activity.dot -o report/activity.svg
	cd report && pandoc report.md --pdf-engine=xelatex -V papersize=a4 \
		-V geometry:margin=1.8cm -V fontsize=10pt -V mainfont="DejaVu Serif" \
		-V sansfont="DejaVu Sans" -V monofont="DejaVu Sans Mono" -o report.pdf
	@echo "make report: wrote report/report.pdf"

# The speed/accuracy trade of each knob: docs/trade.md and its SVG plots.
trade: raytrace raytrace-diff $(BUILD)/raytrace-float $(BUILD)/scenegen
	sh tests/bench/trade.sh ./raytrace ./raytrace-diff $(BUILD)/raytrace-float $(BUILD)/scenegen
	sh tests/bench/gicache.sh ./raytrace ./raytrace-diff

# The irradiance cache's error against time: docs/gicache.md and its plot
# (GICACHE_KEEP_REFS=1: against the last run's references, in build/gicache).
trade-cache: raytrace raytrace-diff
	sh tests/bench/gicache.sh ./raytrace ./raytrace-diff

# The MPL ray tracer's scenes against its program's renders (docs/mpl.md): give
# the path of a checkout of its repository, MPL=DIR.
mpl: raytrace raytrace-diff
	@test -n "$(MPL)" || { echo "make mpl MPL=DIR: DIR a checkout of the MPL ray tracer's repository (docs/mpl.md)" >&2; exit 2; }
	sh tests/bench/mpl.sh '$(MPL)'

# Fuzzing: each parser's target (tests/fuzz/fuzz_*.c), built with clang's
# libFuzzer and sanitizers in $(BUILD)/fuzz; the same targets replay their
# inputs without libFuzzer in `make test` ($(BUILD)/replay).
FUZZ_CC ?= clang
FUZZ_CFLAGS := -std=c11 -g -O1 -ffp-contract=off -fsanitize=address,undefined \
	-fno-sanitize-recover=undefined -Iinclude -Itests/fuzz
FUZZ_OBJ := $(LIB_SRC:src/%.c=$(BUILD)/fuzz/%.o)
.SECONDARY: $(FUZZ_OBJ)

$(BUILD)/fuzz/%.o: src/%.c $(wildcard include/*/*.h src/*/*.h)
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link -c -o $@ $<

$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_scene.h tests/fuzz/fuzz_mesh.h $(FUZZ_OBJ)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_OBJ) -lm

$(BUILD)/replay/%: tests/fuzz/fuzz_%.c tests/fuzz/replay.c tests/fuzz/fuzz_scene.h \
		tests/fuzz/fuzz_mesh.h $(LIB_OBJ) \
		$(wildcard include/*/*.h)
	@mkdir -p $(@D)
	$(CC) $(RT_CPPFLAGS) -Itests/fuzz $(CPPFLAGS) $(RT_CFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ \
		$< tests/fuzz/replay.c $(LIB_OBJ) $(RT_LDLIBS) $(LDLIBS)

fuzz: $(FUZZ_TARGETS:%=$(BUILD)/fuzz/fuzz_%)
	sh tests/fuzz/fuzz.sh $(BUILD) $(FUZZ_TARGETS)

# The long campaign: each target for FUZZ_TIME seconds (default 1800), its
# totals in $(BUILD)/fuzz/totals.md (docs/robustness.md keeps the last).
fuzz-long: $(FUZZ_TARGETS:%=$(BUILD)/fuzz/fuzz_%)
	FUZZ_TIME=$${FUZZ_TIME:-1800} sh tests/fuzz/fuzz.sh $(BUILD) $(FUZZ_TARGETS)

memcheck: raytrace raytrace-diff raytrace-merge
	sh tests/memcheck.sh ./raytrace ./raytrace-diff ./raytrace-merge

clean:
	rm -rf $(BUILD) raytrace raytrace-diff raytrace-merge raytrace.exe raytrace-diff.exe raytrace-merge.exe

-include $(wildcard $(BUILD)/*/*.d $(BUILD)/tests/*.d $(BUILD)/float/*/*.d $(BUILD)/embree/*.d)
