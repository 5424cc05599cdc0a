# SPDX-License-Identifier: Apache-2.0
# tirenv: the two commands of the README, and a few more. CMake does the real work.
BUILD      ?= build
ASAN_BUILD ?= build-asan
PORTABLE_BUILD ?= build-portable
JOBS       ?= 2
DEMO_OUT   ?= out/study
DEMO_205   ?= out/study-205-60R15
PREFIX     ?= /usr/local
FUZZ_SECONDS ?= 60
# Labels of tests to leave out of 'make test' (none by default); e.g. SKIP_LABELS=install.
SKIP_LABELS ?=
skip = $(if $(SKIP_LABELS),-LE '$(SKIP_LABELS)')

.PHONY: all deps deps-test configure cli build wheel test test-asan test-portable test-oldcpu test-slurm demo demo-study demo-study-205 \
        demo-ride bench fuzz python fmu install clean

all: build

# The Debian packages the build, tests and plots need (scripts/deps.sh: installs them as root,
# else prints the apt-get line and fails).
deps:
	@sh scripts/deps.sh

# What the tests need besides: slurm-wlm and munge for the Slurm test (optional: without
# them, or without root, that test reports itself skipped).
deps-test: deps
	@sh scripts/deps.sh --slurm

# The Release build tree under BUILD, configured.
configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

# The library and the CLI alone (what make demo runs), under BUILD.
cli: configure
	@cmake --build $(BUILD) -j $(JOBS) --target tirenv

# Release build under BUILD: the library, CLI, tests, fuzz harnesses, Python module and FMU.
build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Release build and every test, then test-asan.
# The Release run includes the install checks (label install: install into a temporary
# prefix, build tests/package/consumer/ against it, run the installed CLI moved away from the clone)
# and the Slurm scripts on a single-node cluster it starts (label slurm, about 20 s).
test: build deps-test
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(skip)
	@$(MAKE) --no-print-directory test-asan

# The Slurm test alone: scripts/slurm/ on a private single-node cluster (needs root).
test-slurm: build deps-test
	@cd $(BUILD) && ctest --output-on-failure -L slurm

# Debug build under AddressSanitizer + UBSan in ASAN_BUILD, and its tests: all but the labels
# slow, install, slurm and interop (and no fuzz harnesses: TIRENV_FUZZ=OFF; make test ran them).
# At -O1: the sanitizers find the same errors, and the tests take about half the time of -O0;
# -O2, measured too, saved 5 to 19 % of the longest tests' CPU and cost 42 % more to compile.
# Debug information -g1, line tables only: the sanitizers' reports still name file and line
# (UBSan's carry their own), and the compiler takes 11 % less time than with -g; configure
# ASAN_BUILD with -g to look at variables in a debugger.
# Some tests take a stated smaller case there, the same code over fewer cases (the sanitizers
# look for memory errors, not for the numbers, which the Release run checks in full):
# test_ride_dynamic, test_onetire, test_fmt, cli_ring, cli_tir, cli_fifo, cli_roads,
# cli_roads_grade and cli_stream_jobs (tests/CMakeLists.txt, TIRENV_TEST_SANITIZED); cli_fifo and
# cli_sweep leave their whole study (its network's training) to the Release run.
test-asan: deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DTIRENV_SANITIZE=ON \
	    -DTIRENV_FUZZ=OFF '-DCMAKE_C_FLAGS_DEBUG=-g1 -O1' >/dev/null
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	@cd $(ASAN_BUILD) && ctest --output-on-failure -j $(JOBS) -LE 'slow|install|slurm|interop$(if $(SKIP_LABELS),|$(SKIP_LABELS))'

# The generic C paths (-DTIRENV_PORTABLE=ON: no SSE2 intrinsics, no AVX2 kernels, no
# per-processor clones; what a processor other than x86-64 compiles) in PORTABLE_BUILD: its
# Release tests but the labels slow, install, slurm, interop and fuzz, then its envelopes
# against BUILD's byte for byte (scripts/springs-bitcmp.sh: 75 cases, the springs model, the
# ring and the rigid disc). 3 to 4 minutes on 2 cores; not part of make test, which stays
# within 10 minutes.
test-portable: cli
	@cmake -S . -B $(PORTABLE_BUILD) -DCMAKE_BUILD_TYPE=Release -DTIRENV_PORTABLE=ON >/dev/null
	@cmake --build $(PORTABLE_BUILD) -j $(JOBS)
	@cd $(PORTABLE_BUILD) && ctest --output-on-failure -j $(JOBS) -LE 'slow|install|slurm|interop|fuzz'
	@TIRENV_DATA=$(CURDIR)/data sh scripts/springs-bitcmp.sh $(BUILD)/tirenv $(PORTABLE_BUILD)/tirenv \
	    $(PORTABLE_BUILD)/bitcmp

# The CLI on an emulated x86-64 without AVX, AVX2 and FMA (qemu-x86_64 -cpu Nehalem), against
# this machine's run (scripts/oldcpu.sh: the 75 envelopes of springs-bitcmp.sh byte for byte,
# the 205/60R15 data set rebuilt). Installs qemu-user. About a minute; not part of make test.
test-oldcpu: cli
	@sh scripts/deps.sh --oldcpu
	@TIRENV_DATA=$(CURDIR)/data sh scripts/oldcpu.sh $(BUILD)/tirenv $(BUILD)/oldcpu

# The Python module in place under $(BUILD)/python (python/README.md), and the FMI 2.0
# co-simulation FMU $(BUILD)/tirenv_effective_road.fmu (fmu/README.md); both are also part of
# 'make build'.
python: build
	@cmake --build $(BUILD) -j $(JOBS) --target python

fmu: build
	@cmake --build $(BUILD) -j $(JOBS) --target fmu

# A wheel of the Python module carrying libtirenv ($(BUILD)/wheel/tirenv-*.whl): install it
# with 'pip install --no-index' into any virtual environment (python/README.md).
wheel: build
	@cmake --build $(BUILD) -j $(JOBS) --target wheel

# The paper's study on the embedded (simulated) data set: fit, train, compare, report; the same
# on the second one, the 205/60R15 car tire's made by its MF-Swift cam. Then its next step,
# the tractor ride: over a cleat at three speeds (the README's picture), and over a 1 km
# ISO 8608 class C road at 10 km/h, point contact against the enveloping models. The two
# studies run side by side on JOBS cores, the rides after the tractor's study (they take its
# network); -Otarget keeps each part's lines together. Each command also runs its own items
# on --jobs $(JOBS) threads, so that a study left alone (the other one done) still has every
# core; the outputs are the same for any --jobs. The road's bumps are all lower than
# the network's lowest trained cleat: its curves there are that cleat's scaled down
# (docs/models.md section 12), an extrapolation, hence --extrapolate.
# It builds the library and the CLI only (make cli); tests, fuzzers, Python and FMU have their
# own targets.
demo: cli
	@$(MAKE) --no-print-directory -j $(JOBS) -Otarget demo-study-205 demo-ride

# The tractor's study alone, into DEMO_OUT, with the CLI already built (demo-ride's nn model
# uses its nn.json).
demo-study:
	@$(BUILD)/tirenv study --jobs $(JOBS) -o $(DEMO_OUT)

# The 205/60R15 car tire's study alone, into DEMO_205.
demo-study-205:
	@$(BUILD)/tirenv study --jobs $(JOBS) --data data/dataset-205-60R15 -o $(DEMO_205)

# The tractor's rides, after demo-study: over the cleat (out/ride-cleat/) and the road
# (out/ride-road/). The tires' 8.7 and 13.3 kN are 0.19 and 0.24 m patches, below the network's
# trained 0.28 m (docs/models.md section 14.3): its inputs are extrapolations, hence --extrapolate.
demo-ride: demo-study
	@$(BUILD)/tirenv ride --cleat 0.30,0.05 --speed 5km/h,10km/h,15km/h \
	    --model point,springs,cam,nn --nn $(DEMO_OUT)/nn.json --extrapolate \
	    --enveloping static,dynamic --jobs $(JOBS) --out-dir out/ride-cleat
	@mkdir -p out/ride-road
	@$(BUILD)/tirenv road --class C --length 1000 --dx 0.01 --seed 1 -o out/ride-road/road.csv
	@$(BUILD)/tirenv ride --profile out/ride-road/road.csv --speed 10km/h --dx 0.01 \
	    --model point,rigid,springs,cam,nn --nn $(DEMO_OUT)/nn.json --extrapolate \
	    --enveloping static,dynamic \
	    --jobs $(JOBS) --out-dir out/ride-road

# Speed figures: the models and solvers (tirenv bench), then the network and its trainers
# against FANN, the benchmark-only peer (scripts/deps.sh --bench installs libfann-dev).
bench: build
	@sh scripts/deps.sh --bench
	@cmake -S . -B $(BUILD) >/dev/null && cmake --build $(BUILD) -j $(JOBS) --target tirenv-bench-nn
	@$(BUILD)/tirenv bench
	@$(BUILD)/bench/tirenv-bench-nn

# Every libFuzzer harness (tests/fuzz/, built with clang, ASan and UBSan) for FUZZ_SECONDS
# each, one after the other; make test runs them for a few seconds. New inputs collect in
# $(BUILD)/fuzz-work/<parser>/corpus, findings beside it.
fuzz: build
	@cd $(BUILD) && FUZZ_SECONDS=$(FUZZ_SECONDS) ctest -L fuzz --output-on-failure \
	    --timeout $$(($(FUZZ_SECONDS) + 600))

# Installs the CLI, libtirenv (.so and .a), headers, tirenv.pc, the CMake package, man pages
# and data under PREFIX (default /usr/local); DESTDIR stages it under another root.
install: build
	@DESTDIR='$(DESTDIR)' cmake --install $(BUILD) --prefix '$(PREFIX)'

# Removes the build trees and out/ (the demo's outputs).
clean:
	rm -rf $(BUILD) $(ASAN_BUILD) $(PORTABLE_BUILD) out
