# tirenv: the two commands of the README, and a few more. CMake does the real work.
BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= 2
DEMO_OUT   ?= out/study
PREFIX     ?= /usr/local
# Labels of tests to leave out of 'make test' (none by default); e.g. SKIP_LABELS=install.
SKIP_LABELS ?=
skip = $(if $(SKIP_LABELS),-LE '$(SKIP_LABELS)')

.PHONY: all deps deps-test build test test-asan test-slurm demo bench python fmu install clean

all: build

deps:
	@sh scripts/deps.sh

# What the tests need besides: slurm-wlm and munge for the Slurm test (optional: without
# them, or without root, that test reports itself skipped).
deps-test: deps
	@sh scripts/deps.sh --slurm

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# Release build and tests, then the same tests under AddressSanitizer + UBSan.
# The Release run includes the install checks (label install: install into a temporary
# prefix, build tests/consumer/ against it, run the installed CLI moved away from the clone)
# and the Slurm scripts on a single-node cluster it starts (label slurm, about 20 s).
test: build deps-test
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(skip)
	@$(MAKE) --no-print-directory test-asan

# The Slurm test alone: scripts/slurm/ on a private single-node cluster (needs root).
test-slurm: build deps-test
	@cd $(BUILD) && ctest --output-on-failure -L slurm

test-asan: deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DTIRENV_SANITIZE=ON >/dev/null
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	@cd $(ASAN_BUILD) && ctest --output-on-failure -j $(JOBS) -LE 'slow|install|slurm$(if $(SKIP_LABELS),|$(SKIP_LABELS))'

# The Python module in place under $(BUILD)/python (python/README.md), and the FMI 2.0
# co-simulation FMU $(BUILD)/tirenv_effective_road.fmu (fmu/README.md); both are also part of
# 'make build'.
python: build
	@cmake --build $(BUILD) -j $(JOBS) --target python

fmu: build
	@cmake --build $(BUILD) -j $(JOBS) --target fmu

# The paper's study on the embedded (simulated) data set: fit, train, compare, report. Then
# its next step, the tractor ride: over a cleat at three speeds (the README's picture), and
# over a 1 km ISO 8608 class C road at 10 km/h, point contact against the enveloping models.
# The road's bumps are all lower than the network's lowest trained cleat: its curves there are
# that cleat's scaled down (docs/models.md section 12), an extrapolation, hence --extrapolate.
demo: build
	@$(BUILD)/tirenv study -o $(DEMO_OUT)
	@$(BUILD)/tirenv ride --cleat 0.30,0.05 --speed 5km/h,10km/h,15km/h \
	    --model point,springs,cam,nn --nn $(DEMO_OUT)/nn.json --out-dir out/ride-cleat
	@mkdir -p out/ride-road
	@$(BUILD)/tirenv road --class C --length 1000 --dx 0.01 --seed 1 -o out/ride-road/road.csv
	@$(BUILD)/tirenv ride --profile out/ride-road/road.csv --speed 10km/h --dx 0.01 \
	    --model point,rigid,springs,cam,nn --nn $(DEMO_OUT)/nn.json --extrapolate \
	    --out-dir out/ride-road

# Speed figures: the models and solvers (tirenv bench), then the network and its trainers
# against FANN, the benchmark-only peer (scripts/deps.sh --bench installs libfann-dev).
bench: build
	@sh scripts/deps.sh --bench
	@cmake -S . -B $(BUILD) >/dev/null && cmake --build $(BUILD) -j $(JOBS) --target tirenv-bench-nn
	@$(BUILD)/tirenv bench
	@$(BUILD)/bench/tirenv-bench-nn

# Installs the CLI, libtirenv (.so and .a), headers, tirenv.pc, the CMake package, man pages
# and data under PREFIX (default /usr/local); DESTDIR stages it under another root.
install: build
	@DESTDIR='$(DESTDIR)' cmake --install $(BUILD) --prefix '$(PREFIX)'

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) out
