# tirenv: the two commands of the README, and a few more. CMake does the real work.
BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= 2
DEMO_OUT   ?= out/study

.PHONY: all deps build test test-asan demo bench clean

all: build

deps:
	@sh scripts/deps.sh

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# Release build and tests, then the same tests under AddressSanitizer + UBSan.
test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory test-asan

test-asan: deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DTIRENV_SANITIZE=ON >/dev/null
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	@cd $(ASAN_BUILD) && ctest --output-on-failure -j $(JOBS) -LE slow

# The paper's study on the embedded (simulated) data set: fit, train, compare, report.
demo: build
	@$(BUILD)/tirenv study -o $(DEMO_OUT)

# Speed figures: the models and solvers (tirenv bench), then the network and its trainers
# against FANN, the benchmark-only peer (scripts/deps.sh --bench installs libfann-dev).
bench: build
	@sh scripts/deps.sh --bench
	@cmake -S . -B $(BUILD) >/dev/null && cmake --build $(BUILD) -j $(JOBS) --target tirenv-bench-nn
	@$(BUILD)/tirenv bench
	@$(BUILD)/bench/tirenv-bench-nn

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) out
